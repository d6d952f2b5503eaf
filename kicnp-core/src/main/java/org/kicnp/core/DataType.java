package org.kicnp.core;

import java.util.Locale;
import java.util.Optional;

/** The slot data types. {@code xmlName} is the spelling of the paper's XML format (Table 4). */
public enum DataType {
    /** An instance frame; the slot's argument names the class it must be an instance of. */
    INSTANCE("TYPE_INSTANCE"),
    STRING("TYPE_STR"),
    INTEGER("TYPE_INT"),
    FLOAT("TYPE_FLOAT"),
    BOOLEAN("TYPE_BOOL"),
    /** A reference to any frame, class or instance; an argument, if given, names a class it must descend from. */
    FRAME("TYPE_FRAME"),
    /** A list; the argument names the item type ({@code TYPE_STR} when absent) or a class for a list of instances. */
    LIST("TYPE_LIST");

    private final String xmlName;

    DataType(String xmlName) {
        this.xmlName = xmlName;
    }

    public String xmlName() {
        return xmlName;
    }

    /**
     * Reads a type as the paper writes it. Accepts the XML names ({@code TYPE_STR}), the enum names and the
     * words of Table 3 ({@code Instance}, {@code String}), case-insensitively.
     */
    public static Optional<DataType> parse(String text) {
        String t = text.strip().toUpperCase(Locale.ROOT);
        if (t.startsWith("TYPE_")) {
            t = t.substring(5);
        }
        return Optional.ofNullable(switch (t) {
            case "INSTANCE" -> INSTANCE;
            case "STR", "STRING", "TEXT" -> STRING;
            case "INT", "INTEGER", "LONG" -> INTEGER;
            case "FLOAT", "DOUBLE", "REAL", "NUMBER" -> FLOAT;
            case "BOOL", "BOOLEAN" -> BOOLEAN;
            case "FRAME", "REF", "FRAMEREF" -> FRAME;
            case "LIST" -> LIST;
            default -> null;
        });
    }
}
