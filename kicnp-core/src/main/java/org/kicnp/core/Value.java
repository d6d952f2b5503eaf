package org.kicnp.core;

import static java.util.Objects.requireNonNull;

import java.util.List;

/** A slot value: a closed set of typed values. Absent values are {@code Optional.empty()}, never a null. */
public sealed interface Value permits Value.Str, Value.Int, Value.Real, Value.Bool, Value.Ref, Value.Lst {

    /** The data type this value naturally belongs to. */
    DataType type();

    /** The canonical text of the value, as the XML format writes it. Lists have no single text form. */
    String text();

    static Value of(String s) {
        return new Str(s);
    }

    static Value of(long n) {
        return new Int(n);
    }

    static Value of(double d) {
        return new Real(d);
    }

    static Value of(boolean b) {
        return b ? Bool.TRUE : Bool.FALSE;
    }

    static Value ref(String frame) {
        return new Ref(frame);
    }

    /** A string value. */
    record Str(String value) implements Value {
        public Str {
            requireNonNull(value, "value");
        }

        @Override public DataType type() {
            return DataType.STRING;
        }

        @Override public String text() {
            return value;
        }

        /* Written out: values are hash keys on the hot paths of matching, where the generated methods cost more. */
        @Override public boolean equals(Object o) {
            return o instanceof Str t && t.value.equals(value);
        }

        @Override public int hashCode() {
            return value.hashCode();
        }
    }

    /** A 64-bit integer value. */
    record Int(long value) implements Value {
        @Override public DataType type() {
            return DataType.INTEGER;
        }

        @Override public String text() {
            return Long.toString(value);
        }

        /* Written out: values are hash keys on the hot paths of matching, where the generated methods cost more. */
        @Override public boolean equals(Object o) {
            return o instanceof Int i && i.value == value;
        }

        @Override public int hashCode() {
            return Long.hashCode(value);
        }
    }

    /** A floating-point value. */
    record Real(double value) implements Value {
        @Override public DataType type() {
            return DataType.FLOAT;
        }

        @Override public String text() {
            return Double.toString(value);
        }

        /* Written out: values are hash keys on the hot paths of matching, where the generated methods cost more. */
        @Override public boolean equals(Object o) {
            return o instanceof Real r && Double.compare(r.value, value) == 0;
        }

        @Override public int hashCode() {
            return Double.hashCode(value);
        }
    }

    /** A boolean value, written TRUE or FALSE as the paper writes its flags. */
    record Bool(boolean value) implements Value {
        static final Bool TRUE = new Bool(true);
        static final Bool FALSE = new Bool(false);

        @Override public DataType type() {
            return DataType.BOOLEAN;
        }

        @Override public String text() {
            return value ? "TRUE" : "FALSE";
        }
    }

    /** A reference to a frame by name: the value of an instance or frame slot. */
    record Ref(String frame) implements Value {
        public Ref {
            requireNonNull(frame, "frame");
            if (frame.isBlank()) {
                throw new IllegalArgumentException("A frame reference needs a frame name.");
            }
        }

        @Override public DataType type() {
            return DataType.FRAME;
        }

        @Override public String text() {
            return frame;
        }

        /* Written out: values are hash keys on the hot paths of matching, where the generated methods cost more. */
        @Override public boolean equals(Object o) {
            return o instanceof Ref r && r.frame.equals(frame);
        }

        @Override public int hashCode() {
            return frame.hashCode();
        }
    }

    /** An immutable list of values. */
    record Lst(List<Value> items) implements Value {
        public Lst {
            items = List.copyOf(items);
        }

        @Override public DataType type() {
            return DataType.LIST;
        }

        @Override public String text() {
            StringBuilder sb = new StringBuilder("[");
            for (int i = 0; i < items.size(); i++) {
                sb.append(i == 0 ? "" : ", ").append(items.get(i).text());
            }
            return sb.append(']').toString();
        }
    }

    /**
     * Parses the text of a scalar value for a slot of the given type.
     *
     * @throws IllegalArgumentException with a sentence naming the type when the text does not fit it
     */
    static Value parse(DataType type, String text) {
        requireNonNull(type, "type");
        requireNonNull(text, "text");
        String t = text.strip();
        return switch (type) {
            case STRING -> new Str(text);
            case INTEGER -> {
                try {
                    yield new Int(Long.parseLong(t));
                } catch (NumberFormatException e) {
                    throw new IllegalArgumentException(t.matches("[+-]?[0-9]+")
                            ? "'" + text + "' is too large for an integer: TYPE_INT holds whole numbers from "
                                    + Long.MIN_VALUE + " to " + Long.MAX_VALUE + "."
                            : "'" + text + "' is not an integer.");
                }
            }
            case FLOAT -> {
                double d;
                try {
                    d = Double.parseDouble(t);
                } catch (NumberFormatException e) {
                    throw new IllegalArgumentException("'" + text + "' is not a number.");
                }
                // NaN equals nothing, orders against nothing and has no JSON form (the wire, the editor): refuse it.
                if (Double.isNaN(d)) {
                    throw new IllegalArgumentException("'" + text + "' is not a number: TYPE_FLOAT holds numbers (and "
                            + "Infinity or -Infinity), not NaN.");
                }
                // A finite number too large for a double would silently become Infinity; only "Infinity" means that.
                if (Double.isInfinite(d) && !t.contains("Infinity")) {
                    throw new IllegalArgumentException("'" + text + "' is too large for a float: TYPE_FLOAT holds "
                            + "numbers up to about 1.8e308 (write Infinity if that is what you mean).");
                }
                yield new Real(d);
            }
            case BOOLEAN -> switch (t.toUpperCase(java.util.Locale.ROOT)) {
                case "TRUE", "YES", "1" -> Bool.TRUE;
                case "FALSE", "NO", "0" -> Bool.FALSE;
                default -> throw new IllegalArgumentException("'" + text + "' is not TRUE or FALSE.");
            };
            case INSTANCE, FRAME -> new Ref(t);
            case LIST -> throw new IllegalArgumentException("A list value is written as ITEM elements, not as text.");
        };
    }
}
