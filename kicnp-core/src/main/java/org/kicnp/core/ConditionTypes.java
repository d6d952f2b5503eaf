package org.kicnp.core;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Function;

/**
 * Declarative conditions that can never hold because of types: a constant of another kind than the value it is
 * compared with (the text "3" against a TYPE_INT slot: numbers and texts never compare equal, nor in order), a range
 * whose low end is above its high end, or a path into a slot that holds no instance. The engine would silently never
 * fire such a frame; the knowledge base refuses it, naming frame and slot. The compared value's type is the slot's
 * own, or, for one step into the instance it holds ({@code .status == "ended"}), the type the slot's argument class
 * declares for that step; longer paths are not checked.
 */
final class ConditionTypes {
    private ConditionTypes() {
    }

    static List<Problem> problems(Function<String, Frame> lookup, Frame f, Slot own) {
        Condition c = own.condition();
        if (c.testedPath().isEmpty()) {
            return List.of();
        }
        List<String> left = c.testedPath().get();
        String where = "Slot '" + own.name() + "' of frame '" + f.name() + "'";
        List<Problem> out = new ArrayList<>();
        if (!left.isEmpty() && own.type() != DataType.INSTANCE && own.type() != DataType.FRAME) {
            out.add(Problem.of(f.name(), own.name(), where + " has the condition '" + c.text() + "' on '."
                    + String.join(".", left) + "', but the slot holds " + own.type().xmlName()
                    + ", not an instance: the path leads nowhere."));
            return out;
        }
        Optional<DataType> compared = comparedType(lookup, own, left);
        if (compared.isEmpty()) {
            return out;
        }
        for (Operand o : c.operands()) {
            if (o instanceof Operand.Constant k && !comparable(compared.get(), k.value())) {
                out.add(Problem.of(f.name(), own.name(), where + " has the condition '" + c.text()
                        + "', which compares a " + compared.get().xmlName() + " value with " + k.text()
                        + ": they never compare, so it can never hold."));
            }
        }
        if (c instanceof Condition.Between b && b.low() instanceof Operand.Constant lo
                && b.high() instanceof Operand.Constant hi && isNumber(lo.value()) && isNumber(hi.value())
                && number(lo.value()) > number(hi.value())) {
            out.add(Problem.of(f.name(), own.name(), where + " has the condition '" + c.text() + "', whose low end is "
                    + "above its high end, so it can never hold."));
        }
        return out;
    }

    /** The type of the value the condition compares, when it can be told without following more than one step. */
    private static Optional<DataType> comparedType(Function<String, Frame> lookup, Slot own, List<String> left) {
        if (left.isEmpty()) {
            return Optional.of(own.type());
        }
        if (left.size() > 1 || own.type() != DataType.INSTANCE) {
            return Optional.empty();
        }
        return own.argument().map(lookup).flatMap(cls -> Inheritance.slot(lookup, cls, left.getFirst()))
                .map(e -> e.slot().type());
    }

    private static boolean comparable(DataType type, Value v) {
        return switch (type) {
            case INTEGER, FLOAT -> isNumber(v);
            case STRING -> v instanceof Value.Str;
            case BOOLEAN -> v instanceof Value.Bool;
            default -> true; // instances and frames compare by name, lists item by item: not checked here
        };
    }

    private static boolean isNumber(Value v) {
        return v instanceof Value.Int || v instanceof Value.Real;
    }

    private static double number(Value v) {
        return v instanceof Value.Int i ? i.value() : ((Value.Real) v).value();
    }
}
