package org.kicnp.inference;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.function.BiFunction;
import java.util.function.Function;
import java.util.function.Supplier;
import org.kicnp.core.Condition;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Value;

/**
 * Backward chaining: to find the instances of a class, take those that exist, then for every behavior frame at or
 * below the class find, slot by slot, instances that exist or could themselves be derived, and keep the combinations
 * whose conditions hold. A script condition is decided by running it when every instance of the binding exists (as
 * forward chaining runs it when it matches the binding: side-effect free, it is given {@code s} only; for at most
 * {@code maxAnswers} bindings per question) and assumed when the binding holds a hypothetical instance, whose slots
 * are not known before its {@code onInstantiate} would run.
 * Read-only: nothing is created, no action or {@code onInstantiate} runs. Bounded in depth, answers and combinations
 * tried ({@link QuestionTooBroadException}); a frame is not used again inside its own proof.
 */
final class BackwardChainer {
    private static final String HYPO = "?";
    private final KnowledgeBase kb;
    private final EngineOptions options;
    private final Supports supports;
    private final Supplier<List<Rule>> rules;
    /** The compiled rule of a behavior frame ({@link ForwardChainer#rule}). */
    private final Function<String, Optional<Rule>> rule;
    /** Why a script condition of a binding of real instances is false or fails, if one is ({@link ScriptCalls}). */
    private final BiFunction<Rule, Map<String, String>, Optional<String>> scriptFails;
    /** The bindings whose script conditions the current question has run (at most {@code maxAnswers}). */
    private int scriptRuns;
    /** The class the current question is about, and the combinations of instances it has tried. */
    private String question;
    private int steps;

    BackwardChainer(KnowledgeBase kb, EngineOptions options, Supports supports, Supplier<List<Rule>> rules,
                    Function<String, Optional<Rule>> rule,
                    BiFunction<Rule, Map<String, String>, Optional<String>> scriptFails) {
        this.kb = kb;
        this.options = options;
        this.supports = supports;
        this.rules = rules;
        this.rule = rule;
        this.scriptFails = scriptFails;
    }

    List<Answer> ask(String className, Map<String, Value> partial) {
        if (!kb.contains(className)) {
            throw new org.kicnp.core.UnknownFrameException(className);
        }
        scriptRuns = 0;
        question = className;
        steps = 0;
        Map<String, Map<String, Value>> hypo = new HashMap<>();
        Conditions conds = new Conditions((f, s) -> read(hypo, f, s));
        List<Answer> out = new ArrayList<>();
        for (Frame f : kb.instancesOf(className)) {
            if (out.size() >= options.maxAnswers()) {
                break;
            }
            if (partial.entrySet().stream().allMatch(e -> kb.value(f.name(), e.getKey()).map(v -> Values.test(v,
                    Condition.Op.EQ, e.getValue())).orElse(false))) {
                Map<String, String> slots = new LinkedHashMap<>();
                supports.derivation(f.name()).ifPresent(d -> slots.putAll(d.binding()));
                out.add(new Answer(f.parent().orElseThrow(), Optional.of(f.name()), slots,
                        new Proof.Exists(f.name(), f.parent().orElseThrow())));
            }
        }
        for (Rule r : rules.get()) {
            if (kb.isA(r.frame(), className)) {
                for (Proof.Derivable p : derive(r, partial, 1, Set.of(r.frame()), hypo, conds)) {
                    if (out.size() >= options.maxAnswers()) {
                        return out;
                    }
                    Map<String, String> slots = new LinkedHashMap<>();
                    p.slots().forEach((s, sub) -> slots.put(s, sub instanceof Proof.Exists e ? e.instance()
                            : HYPO + sub.className()));
                    out.add(new Answer(r.frame(), Optional.empty(), slots, p));
                }
            }
        }
        return out;
    }

    private List<Proof> proofs(String cls, int depth, Set<String> using, Map<String, Map<String, Value>> hypo,
                               Conditions conds) {
        List<Proof> out = new ArrayList<>();
        kb.forEachInstanceOf(cls, f -> out.add(new Proof.Exists(f.name(), f.parent().orElseThrow())));
        if (depth < options.maxProofDepth()) {
            for (Rule r : rules.get()) {
                if (!using.contains(r.frame()) && kb.isA(r.frame(), cls)) {
                    Set<String> next = new HashSet<>(using);
                    next.add(r.frame());
                    out.addAll(derive(r, Map.of(), depth + 1, next, hypo, conds));
                }
            }
        }
        return out;
    }

    private List<Proof.Derivable> derive(Rule r, Map<String, Value> partial, int depth, Set<String> using,
                                         Map<String, Map<String, Value>> hypo, Conditions conds) {
        if (!inheritsBinding(r, partial)) {
            return List.of();
        }
        List<List<Proof>> options = new ArrayList<>();
        for (SlotPattern p : r.required()) {
            Value want = partial.get(p.slot());
            if (want == null) {
                options.add(proofs(p.argument(), depth, using, hypo, conds));
            } else if (want instanceof Value.Ref ref) {
                options.add(kb.frame(ref.frame()).filter(f -> f.isInstance() && kb.isA(f.name(), p.argument()))
                        .<List<Proof>>map(f -> List.of(new Proof.Exists(f.name(), f.parent().orElseThrow())))
                        .orElse(List.of()));
            } else {
                return List.of(); // an instance slot holds a reference, never this value
            }
        }
        List<Proof.Derivable> out = new ArrayList<>();
        combine(r, options, 0, new LinkedHashMap<>(), out, hypo, conds);
        return out;
    }

    /**
     * Whether an instance the rule would derive holds the bindings of the slots that are not its instance slots: it
     * inherits their values from the behavior frame, so they are tested as an existing instance's are (a slot the
     * frame has not holds nothing, and matches no binding). An optional instance slot's binding is not tested: what it
     * holds depends on what fits when the rule fires.
     */
    private boolean inheritsBinding(Rule r, Map<String, Value> partial) {
        for (Map.Entry<String, Value> e : partial.entrySet()) {
            if (r.pattern(e.getKey()).isEmpty() && !kb.value(r.frame(), e.getKey())
                    .map(v -> Values.test(v, Condition.Op.EQ, e.getValue())).orElse(false)) {
                return false;
            }
        }
        return true;
    }

    private void combine(Rule r, List<List<Proof>> options, int k, Map<String, Proof> chosen,
                         List<Proof.Derivable> out, Map<String, Map<String, Value>> hypo, Conditions conds) {
        if (out.size() >= this.options.maxAnswers()) {
            return;
        }
        if (k == options.size()) {
            if (++steps > this.options.maxQuestionSteps()) {
                throw new QuestionTooBroadException(question, steps - 1);
            }
            Map<String, String> binding = new LinkedHashMap<>();
            chosen.forEach((s, p) -> binding.put(s, name(p, hypo)));
            if (new HashSet<>(binding.values()).size() < binding.size() || blocked(r, binding)
                    || claimsClash(r, binding, hypo)) {
                return;
            }
            // Run the scripts of a binding of real instances, up to a budget per question: a question over many
            // instances whose scripts all say no must not hold the engine for a script run per combination.
            boolean decide = r.scripted() && scriptRuns < this.options.maxAnswers()
                    && binding.values().stream().noneMatch(n -> n.startsWith(HYPO));
            List<String> assumptions = new ArrayList<>();
            for (SlotPattern p : r.required()) {
                if (p.condition() instanceof Condition.Script s) {
                    if (!decide) {
                        assumptions.add(p.slot() + ": " + s.text());
                    }
                } else if (!conds.holds(p.condition(), Value.ref(binding.get(p.slot())), r.frame(), binding)) {
                    return;
                }
            }
            if (decide) {
                scriptRuns++;
                if (scriptFails.apply(r, binding).isPresent()) {
                    return;
                }
            }
            out.add(new Proof.Derivable(r.frame(), chosen, assumptions));
            return;
        }
        for (Proof p : options.get(k)) {
            chosen.put(r.required().get(k).slot(), p);
            combine(r, options, k + 1, chosen, out, hypo, conds);
            chosen.remove(r.required().get(k).slot());
        }
    }

    /**
     * The name a proof's instance goes by while conditions are tested: real, or a hypothetical one made of its frame
     * and binding, so that two proofs of the same frame with the same binding name one instance, as forward chaining
     * makes one (a binding fires once) — and a binding that would need it twice is seen holding one instance twice.
     */
    private String name(Proof p, Map<String, Map<String, Value>> hypo) {
        return switch (p) {
            case Proof.Exists e -> e.instance();
            case Proof.Derivable d -> {
                Map<String, Value> slots = new TreeMap<>();
                d.slots().forEach((s, sub) -> slots.put(s, Value.ref(name(sub, hypo))));
                StringBuilder n = new StringBuilder(HYPO).append(d.frame()).append('(');
                slots.forEach((s, v) -> n.append(s).append('=').append(((Value.Ref) v).frame()).append(';'));
                String name = n.append(')').toString();
                hypo.putIfAbsent(name, slots);
                hypo.putIfAbsent(name + "/class", Map.of("class", Value.of(d.frame())));
                yield name;
            }
        };
    }

    /**
     * Whether two different instances of one proof — the one {@code r} would make with {@code binding}, and the
     * hypothetical ones below it — would claim the same thing, which forward chaining lets only one of them do: the
     * same instance in an unshared slot of the same frame, or the same unique key of the same frame. (Claims of the
     * instances that exist are checked against what live instances hold, by {@link #blocked}.)
     */
    private boolean claimsClash(Rule r, Map<String, String> binding, Map<String, Map<String, Value>> hypo) {
        Map<String, String> owners = new HashMap<>();
        if (!claim(r, binding, "", owners)) {
            return true;
        }
        ArrayDeque<String> todo = new ArrayDeque<>(binding.values());
        Set<String> seen = new HashSet<>();
        while (!todo.isEmpty()) {
            String n = todo.pop();
            if (!n.startsWith(HYPO) || !seen.add(n)) {
                continue;
            }
            Map<String, String> its = new LinkedHashMap<>();
            hypo.get(n).forEach((slot, v) -> its.put(slot, ((Value.Ref) v).frame()));
            Optional<Rule> made = rule.apply(hypo.get(n + "/class").get("class").text());
            if (made.isPresent() && !claim(made.get(), its, n, owners)) {
                return true;
            }
            todo.addAll(its.values());
        }
        return false;
    }

    /** Records what instance {@code id} of rule {@code r} would claim; false when another instance claims it. */
    private static boolean claim(Rule r, Map<String, String> binding, String id, Map<String, String> owners) {
        if (!r.claims()) {
            return true;
        }
        List<String> keys = new ArrayList<>();
        for (SlotPattern p : r.required()) {
            if (!p.shared()) {
                keys.add(Supports.claimKey(r.frame(), p.slot(), binding.get(p.slot())));
            }
        }
        Supports.uniqueKey(r, binding).ifPresent(keys::add);
        for (String k : keys) {
            String owner = owners.putIfAbsent(k, id);
            if (owner != null && !owner.equals(id)) {
                return false;
            }
        }
        return true;
    }

    private Optional<Value> read(Map<String, Map<String, Value>> hypo, String frame, String slot) {
        if (frame.startsWith(HYPO)) {
            Map<String, Value> m = hypo.get(frame);
            if (m == null) {
                return Optional.empty();
            }
            if (m.containsKey(slot)) {
                return Optional.of(m.get(slot));
            }
            String cls = hypo.get(frame + "/class").get("class").text();
            return kb.value(cls, slot);
        }
        return kb.contains(frame) ? kb.value(frame, slot) : Optional.empty();
    }

    /**
     * Whether forward chaining would refuse the binding: it fired already (refraction), an unshared slot's instance
     * or an optional unique slot's instance is claimed, or the frame's unique key is taken by a live instance. What
     * the hypothetical instances of the same proof would claim is {@link #claimsClash}'s.
     */
    private boolean blocked(Rule r, Map<String, String> binding) {
        String[] facts = Activation.factsOf(r, binding);
        return supports.blocked(r, facts, new BindingKey(r.frame(), facts)).isPresent();
    }
}
