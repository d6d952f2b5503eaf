package org.kicnp.inference;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.kicnp.script.ScriptObject;

/**
 * A script condition simple enough to decide without running JavaScript, deciding it as JavaScript does: comparisons
 * of paths of {@code s} and literals, joined by {@code &&}, {@code ||}, {@code !} and parentheses — what most
 * conditions are (Table 5's rows: {@code (s.mDone.frame == "Greeting") && s.mDone.status == "ended"}). A GraalJS run of
 * such a condition costs microseconds when warm and milliseconds for its first runs on a cold JVM; this costs a few
 * member reads, so a platform that has just started answers as fast as one that has run for an hour.
 *
 * <p>The grammar is narrow on purpose, and every value is one whose JavaScript meaning is plain: a text, a number
 * (a Java {@code Long} within ±2<sup>53</sup>, or a {@code Double}), a truth value, {@code null} or a member that is
 * not there ({@code undefined}). Whatever else an evaluation meets — an object compared, a text compared with a
 * number ({@code ==} would convert it), a member read from something that is not an object (a {@code TypeError}),
 * a member that an object's prototype could answer ({@code toString}) — makes it give up ({@link #test} is empty) and
 * the script runs as before. {@code SimpleConditionTest} runs every form against GraalJS.
 *
 * <p>A chain {@code T1 && T2 && ... && Tn} whose first terms are of the grammar and a later one is not (Table 5's
 * {@code s.mDone.frame == "AIBOAction1" && s.mDone.status != "ended" && !/retracted/.test(String(s.mDone.result))}) is
 * decided false when one of those first terms is false, as JavaScript stops there; otherwise the script runs. The
 * text is split only where a split is certain ({@link AndChain}): nothing at its top binds less tightly than
 * {@code &&}, and quotes and regular expressions are skipped.
 *
 * <pre>
 * condition := and ('||' and)*            and := unary ('&&' unary)*
 * unary     := '!' negated | '(' condition ')' | operand op operand | 'true' | 'false'
 * negated   := '!' negated | '(' condition ')' | operand
 * op        := '==' | '!=' | '===' | '!==' | '<' | '<=' | '>' | '>='
 * operand   := 's' ('.' name)+ | text | number | 'true' | 'false' | 'null'       (a trailing ';' is allowed)
 * </pre>
 */
final class SimpleCondition {
    /** Members every JavaScript object may answer from its prototype: a read of one is left to the script. */
    private static final Set<String> PROTOTYPE = Set.of("constructor", "toString", "toLocaleString", "valueOf",
            "hasOwnProperty", "isPrototypeOf", "propertyIsEnumerable");
    private static final double SAFE_INTEGER = 9007199254740992.0; // 2^53
    /** An evaluation met something it does not decide as JavaScript would. */
    private static final class Undecided extends RuntimeException {
        private static final Undecided INSTANCE = new Undecided();

        private Undecided() {
            super(null, null, false, false);
        }
    }

    /** The value of a member that is not there. */
    private static final Object UNDEFINED = new Object();
    /** The value of {@code null}. */
    private static final Object NULL = new Object();
    /** Any object (a view of an instance, a list). */
    private static final Object OBJECT = new Object();

    private sealed interface Node permits Logical, Not, Compare, Operand, Prefix {
    }

    /**
     * The simple first terms of an {@code &&} chain whose next term is not simple: false when one of them is, else
     * undecided (the rest is the script's).
     */
    private record Prefix(List<Node> terms) implements Node {
    }

    private record Logical(boolean and, Node left, Node right) implements Node {
    }

    private record Not(Node operand) implements Node {
    }

    private record Compare(Operand left, String op, Operand right) implements Node {
    }

    /** A path of {@code s} (members, in order) or a literal. */
    private record Operand(List<String> path, Object literal) implements Node {
    }

    private final Node root;

    private SimpleCondition(Node root) {
        this.root = root;
    }

    /** The condition, when its text is one of the simple forms above; empty otherwise. */
    static Optional<SimpleCondition> parse(String source) {
        Optional<Node> whole = parseWhole(source);
        if (whole.isPresent()) {
            return Optional.of(new SimpleCondition(whole.get()));
        }
        // A chain of '&&' whose first terms are simple and a later one is not (a regular expression, a call): those
        // first terms decide it when one is false, as JavaScript stops there; else the script runs.
        List<String> terms = AndChain.terms(source);
        if (terms.size() < 2) {
            return Optional.empty();
        }
        List<Node> decidable = new ArrayList<>();
        for (String term : terms) {
            Optional<Node> n = parseWhole(term);
            if (n.isEmpty()) {
                break;
            }
            decidable.add(n.get());
        }
        return decidable.isEmpty() ? Optional.empty() : Optional.of(new SimpleCondition(new Prefix(decidable)));
    }

    /** The whole text as one condition of the grammar (a trailing ';' allowed), or empty. */
    private static Optional<Node> parseWhole(String source) {
        try {
            Parser p = new Parser(source);
            Node n = p.condition();
            p.skipSpace();
            if (p.at < source.length() && source.charAt(p.at) == ';') {
                p.at++;
                p.skipSpace();
            }
            return p.at == source.length() ? Optional.of(n) : Optional.empty();
        } catch (Undecided e) {
            return Optional.empty();
        }
    }

    /**
     * The condition's truth with {@code s} as its binding, as the script would give it; empty when this evaluation
     * met something it leaves to the script (the script then runs, and reads {@code s} again).
     */
    Optional<Boolean> test(ScriptObject s) {
        try {
            return Optional.of(truth(root, s));
        } catch (Undecided e) {
            return Optional.empty();
        }
    }

    private static boolean truth(Node n, ScriptObject s) {
        return switch (n) {
            case Logical l -> l.and() ? truth(l.left(), s) && truth(l.right(), s)
                    : truth(l.left(), s) || truth(l.right(), s);
            case Not x -> !truthy(x.operand(), s);
            case Compare c -> compare(value(c.left(), s), c.op(), value(c.right(), s));
            case Operand o -> (Boolean) o.literal(); // 'true' or 'false' alone: the parser allows no other
            case Prefix p -> {
                for (Node t : p.terms()) {
                    if (!truth(t, s)) {
                        yield false;
                    }
                }
                throw Undecided.INSTANCE;
            }
        };
    }

    /** ToBoolean of a negated operand or condition. */
    private static boolean truthy(Node n, ScriptObject s) {
        if (!(n instanceof Operand o)) {
            return truth(n, s);
        }
        Object v = value(o, s);
        return switch (v) {
            case Boolean b -> b;
            case Double d -> d != 0 && !d.isNaN();
            case String t -> !t.isEmpty();
            default -> v == OBJECT; // undefined and null are false, objects true
        };
    }

    private static boolean compare(Object l, String op, Object r) {
        if (l == OBJECT || r == OBJECT) {
            throw Undecided.INSTANCE; // identity, or a conversion to a primitive
        }
        return switch (op) {
            case "===" -> strictEquals(l, r);
            case "!==" -> !strictEquals(l, r);
            case "==" -> looseEquals(l, r);
            case "!=" -> !looseEquals(l, r);
            default -> relational(l, op, r);
        };
    }

    private static boolean strictEquals(Object l, Object r) {
        if (l instanceof Double a && r instanceof Double b) {
            return a.doubleValue() == b.doubleValue(); // NaN is not itself, -0 is 0
        }
        return l.getClass() == r.getClass() && l.equals(r) || l == r;
    }

    private static boolean looseEquals(Object l, Object r) {
        boolean lNothing = l == NULL || l == UNDEFINED;
        boolean rNothing = r == NULL || r == UNDEFINED;
        if (lNothing || rNothing) {
            return lNothing && rNothing;
        }
        if (l.getClass() != r.getClass()) {
            throw Undecided.INSTANCE; // a text, number or truth value converted to another type
        }
        return strictEquals(l, r);
    }

    private static boolean relational(Object l, String op, Object r) {
        int c;
        if (l instanceof Double a && r instanceof Double b) {
            if (a.isNaN() || b.isNaN()) {
                return false;
            }
            c = Double.compare(a + 0.0, b + 0.0); // -0 and 0 compare equal
        } else if (l instanceof String a && r instanceof String b) {
            c = a.compareTo(b); // UTF-16 code units, as JavaScript compares texts
        } else {
            throw Undecided.INSTANCE;
        }
        return switch (op) {
            case "<" -> c < 0;
            case "<=" -> c <= 0;
            case ">" -> c > 0;
            default -> c >= 0;
        };
    }

    /** An operand's value: a literal, or the path read from {@code s}. */
    private static Object value(Operand o, ScriptObject s) {
        if (o.path() == null) {
            return o.literal();
        }
        Object at = s;
        for (String member : o.path()) {
            if (!(at instanceof ScriptObject obj)) {
                throw Undecided.INSTANCE; // a member of a text, a list, undefined or null: the script decides
            }
            Optional<Object> v = obj.member(member);
            if (v.isEmpty() && (PROTOTYPE.contains(member) || member.startsWith("__"))) {
                throw Undecided.INSTANCE;
            }
            at = v.isEmpty() ? UNDEFINED : v.get();
        }
        return switch (at) {
            case String t -> t;
            case Boolean b -> b;
            case Long l when Math.abs((double) l) < SAFE_INTEGER -> (double) l;
            case Double d -> d;
            case Integer i -> (double) i;
            case ScriptObject obj -> OBJECT;
            case List<?> list -> OBJECT;
            default -> {
                if (at == UNDEFINED) {
                    yield UNDEFINED;
                }
                throw Undecided.INSTANCE;
            }
        };
    }

    /** Recursive descent over the grammar above; any other text throws {@link Undecided}. */
    private static final class Parser {
        private final String text;
        int at;

        Parser(String text) {
            this.text = text;
        }

        Node condition() {
            Node n = and();
            while (take("||")) {
                n = new Logical(false, n, and());
            }
            return n;
        }

        private Node and() {
            Node n = unary();
            while (take("&&")) {
                n = new Logical(true, n, unary());
            }
            return n;
        }

        /** {@code '!' negated} or {@code '(' condition ')'}; null when neither comes next. */
        private Node prefixed() {
            if (take("!")) {
                return new Not(negated());
            }
            if (take("(")) {
                Node n = condition();
                expect(")");
                return n;
            }
            return null;
        }

        private Node unary() {
            Node prefixed = prefixed();
            if (prefixed != null) {
                return prefixed;
            }
            Operand left = operand();
            String op = operator();
            if (op == null) {
                if (left.path() == null && left.literal() instanceof Boolean) {
                    return left;
                }
                throw Undecided.INSTANCE; // a bare path or literal would make the result that value, not a truth
            }
            return new Compare(left, op, operand());
        }

        private Node negated() {
            Node prefixed = prefixed();
            return prefixed != null ? prefixed : operand();
        }

        private String operator() {
            for (String op : List.of("===", "!==", "==", "!=", "<=", ">=", "<", ">")) {
                if (take(op)) {
                    return op;
                }
            }
            return null;
        }

        private Operand operand() {
            skipSpace();
            if (at >= text.length()) {
                throw Undecided.INSTANCE;
            }
            char c = text.charAt(at);
            if (c == '"' || c == '\'') {
                return new Operand(null, string(c));
            }
            if (c >= '0' && c <= '9') {
                return new Operand(null, number());
            }
            String name = name();
            return switch (name) {
                case "true" -> new Operand(null, Boolean.TRUE);
                case "false" -> new Operand(null, Boolean.FALSE);
                case "null" -> new Operand(null, NULL);
                case "s" -> {
                    List<String> path = new ArrayList<>();
                    while (at < text.length() && text.charAt(at) == '.') {
                        at++;
                        path.add(name());
                    }
                    if (path.isEmpty()) {
                        throw Undecided.INSTANCE;
                    }
                    yield new Operand(List.copyOf(path), null);
                }
                default -> throw Undecided.INSTANCE; // another global: a function, a variable
            };
        }

        /** A name of ASCII letters, digits, '_' and '$', not starting with a digit (no space before or inside). */
        private String name() {
            int start = at;
            while (at < text.length() && isNamePart(text.charAt(at))) {
                at++;
            }
            if (at == start || Character.isDigit(text.charAt(start))) {
                throw Undecided.INSTANCE;
            }
            return text.substring(start, at);
        }

        private static boolean isNamePart(char c) {
            return c >= 'a' && c <= 'z' || c >= 'A' && c <= 'Z' || c >= '0' && c <= '9' || c == '_' || c == '$';
        }

        /** A quoted text with no escapes and no line break (any other is left to the script). */
        private String string(char quote) {
            int end = text.indexOf(quote, at + 1);
            if (end < 0) {
                throw Undecided.INSTANCE;
            }
            String s = text.substring(at + 1, end);
            if (s.indexOf('\\') >= 0 || s.indexOf('\n') >= 0 || s.indexOf('\r') >= 0) {
                throw Undecided.INSTANCE;
            }
            at = end + 1;
            return s;
        }

        /** Decimal digits with an optional fraction, as JavaScript reads them (no exponent, sign or leading zero). */
        private Double number() {
            int start = at;
            while (at < text.length() && Character.isDigit(text.charAt(at))) {
                at++;
            }
            if (at < text.length() && text.charAt(at) == '.') {
                at++;
                int fraction = at;
                while (at < text.length() && Character.isDigit(text.charAt(at))) {
                    at++;
                }
                if (at == fraction) {
                    throw Undecided.INSTANCE;
                }
            }
            if (at < text.length() && (isNamePart(text.charAt(at)) || text.charAt(at) == '.')
                    || text.charAt(start) == '0' && at > start + 1 && text.charAt(start + 1) != '.') {
                throw Undecided.INSTANCE; // 1e3, 0x1f, 1.2.3, 012 (octal in sloppy mode)
            }
            return Double.valueOf(text.substring(start, at));
        }

        private boolean take(String token) {
            skipSpace();
            if (!text.startsWith(token, at)) {
                return false;
            }
            // '=' after '==' or '!=' is '===' / '!==', which are tried first; '&' or '|' alone is a bit operator
            at += token.length();
            return true;
        }

        private void expect(String token) {
            if (!take(token)) {
                throw Undecided.INSTANCE;
            }
        }

        void skipSpace() {
            while (at < text.length() && (text.charAt(at) == ' ' || text.charAt(at) == '\t' || text.charAt(at) == '\n'
                    || text.charAt(at) == '\r')) {
                at++;
            }
        }
    }
}
