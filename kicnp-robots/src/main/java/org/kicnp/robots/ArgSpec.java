package org.kicnp.robots;

import org.kicnp.core.DataType;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

/**
 * One argument of a robot action: its name on the wire (the simulator's, also the slot name in the action frame),
 * its type, and whether it must be given. Platform commands carry arguments as text; {@link #parse} turns the text
 * into the JSON value the simulator wants, with a full-sentence error when it does not fit.
 */
public record ArgSpec(String name, DataType type, boolean required) {
    public ArgSpec {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(type, "type");
        if (type != DataType.STRING && type != DataType.FLOAT && type != DataType.INTEGER && type != DataType.BOOLEAN
                && type != DataType.LIST) {
            throw new IllegalArgumentException("Argument '" + name + "' cannot be of type " + type.xmlName() + ".");
        }
    }

    public static ArgSpec required(String name, DataType type) {
        return new ArgSpec(name, type, true);
    }

    public static ArgSpec optional(String name, DataType type) {
        return new ArgSpec(name, type, false);
    }

    /** The simulator's value for the text: a number, a boolean, a string, or a list of strings (comma-separated). */
    Object parse(String action, String text) {
        String t = text.strip();
        try {
            return switch (type) {
                case FLOAT -> finite(Double.parseDouble(t));
                case INTEGER -> Long.parseLong(t);
                case BOOLEAN -> switch (t.toLowerCase(java.util.Locale.ROOT)) {
                    case "true" -> true;
                    case "false" -> false;
                    default -> throw new NumberFormatException();
                };
                case LIST -> {
                    List<String> items = new ArrayList<>();
                    for (String item : t.split(",")) {
                        items.add(item.strip());
                    }
                    yield List.copyOf(items);
                }
                default -> text;
            };
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("Argument '" + name + "' of " + action + " must be "
                    + describe() + ", not '" + text + "'.");
        }
    }

    private static double finite(double v) {
        if (!Double.isFinite(v)) {
            throw new NumberFormatException();
        }
        return v;
    }

    private String describe() {
        return switch (type) {
            case FLOAT -> "a number";
            case INTEGER -> "an integer";
            case BOOLEAN -> "true or false";
            default -> "text";
        };
    }
}
