package org.kicnp.inference;

import org.kicnp.core.Condition;
import org.kicnp.core.Value;

/** Comparison of slot values: numbers compare across integer and float, text with text, the rest by equality. */
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
            return Double.compare(number(a), number(b));
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

    private static boolean isNumber(Value v) {
        return v instanceof Value.Int || v instanceof Value.Real;
    }

    private static double number(Value v) {
        return v instanceof Value.Int i ? i.value() : ((Value.Real) v).value();
    }
}
