package org.kicnp.inference;

import org.kicnp.core.Condition;
import org.kicnp.core.Value;

/**
 * Comparison of slot values: numbers compare across integer and float (numerically: {@code -0.0 == 0}), text with
 * text, the rest by equality.
 */
final class Values {
    private Values() {
    }

    static boolean test(Value a, Condition.Op op, Value b) {
        Integer cmp = compare(a, b);
        return switch (op) {
            case EQ -> cmp != null ? cmp == 0 : a.equals(b);
            case NE -> cmp != null ? cmp != 0 : !a.equals(b);
            case LT -> cmp != null && cmp < 0;
            case LE -> cmp != null && cmp <= 0;
            case GT -> cmp != null && cmp > 0;
            case GE -> cmp != null && cmp >= 0;
        };
    }

    /** The order of two values, or null when they are not ordered against each other. */
    static Integer compare(Value a, Value b) {
        if (isNumber(a) && isNumber(b)) {
            if (a instanceof Value.Int x && b instanceof Value.Int y) {
                return Long.compare(x.value(), y.value());
            }
            double x = number(a);
            double y = number(b);
            return x < y ? -1 : x > y ? 1 : x == y ? 0 : Double.compare(x, y);
        }
        if (a instanceof Value.Str x && b instanceof Value.Str y) {
            return x.value().compareTo(y.value());
        }
        return null;
    }

    /** A key under which equal values meet in a hash index: integral floats become integers. */
    static Value key(Value v) {
        if (v instanceof Value.Real r && r.value() == Math.rint(r.value()) && !Double.isInfinite(r.value())) {
            return Value.of((long) r.value());
        }
        return v;
    }

    /** The largest integer a double holds exactly: above it, an integer and a float may meet under one key unequal. */
    private static final long EXACT = 1L << 53;

    /**
     * Whether values meeting under this index key (see {@link #key}) are certainly equal by {@link #test} with
     * {@code EQ}, so that a hash look-up decides an equality condition by itself: every key but a large integer,
     * which a float beyond 2^53 may round to.
     */
    static boolean exactKey(Value key) {
        return !(key instanceof Value.Int i) || (i.value() <= EXACT && i.value() >= -EXACT);
    }

    private static boolean isNumber(Value v) {
        return v instanceof Value.Int || v instanceof Value.Real;
    }

    private static double number(Value v) {
        return v instanceof Value.Int i ? i.value() : ((Value.Real) v).value();
    }
}
