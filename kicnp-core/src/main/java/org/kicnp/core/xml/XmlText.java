package org.kicnp.core.xml;

import java.io.IOException;
import org.kicnp.core.KnowledgeException;

/**
 * Writes free text as XML element content. Text with {@code <}, {@code &} or a line break goes in CDATA, so scripts
 * stay readable; other text is escaped. A carriage return would be lost to XML's line-end normalisation inside CDATA,
 * so such text is escaped with character references instead. Text that plain would read as absent (empty, white
 * space, {@code NULL}) goes in CDATA too, which the reader takes as written: {@code <![CDATA[]]>} is the empty string.
 */
final class XmlText {
    private XmlText() {
    }

    static void write(CharSink out, String text, String where) throws IOException {
        if (text.length() > SecureXml.MAX_TEXT) {
            throw new KnowledgeException("The " + where + " holds " + text.length() + " characters of text, more than "
                    + "the " + SecureXml.MAX_TEXT + " a knowledge file may hold in one element.");
        }
        boolean markup = false;
        boolean cr = false;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c == '<' || c == '&' || c == '\n') {
                markup = true;
            } else if (c == '\r') {
                cr = true;
            } else if (Character.isSurrogate(c)) {
                if (Character.isHighSurrogate(c) && i + 1 < text.length() && Character.isLowSurrogate(text.charAt(i + 1))) {
                    i++;
                } else {
                    throw new KnowledgeException("The " + where + " holds a lone surrogate U+"
                            + String.format("%04X", (int) c) + ", which is not a character and cannot be written.");
                }
            } else if (c < 0x20 && c != '\t' || c == 0xFFFE || c == 0xFFFF) {
                throw new KnowledgeException("The " + where + " holds the character U+"
                        + String.format("%04X", (int) c) + ", which XML 1.0 cannot represent.");
            }
        }
        if (Located.isNull(text)) {
            // White space or NULL: no markup or "]]>" to split; a carriage return follows an empty section, escaped.
            out.write("<![CDATA[");
            out.write(cr ? "" : text);
            out.write("]]>");
            if (!cr) {
                return;
            }
        } else if (markup && !cr) {
            out.write("<![CDATA[");
            out.write(text.replace("]]>", "]]]]><![CDATA[>"));
            out.write("]]>");
            return;
        }
        if (!markup && !cr && text.indexOf('>') < 0) {
            out.write(text);
            return;
        }
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            switch (c) {
                case '<' -> out.write("&lt;");
                case '>' -> out.write("&gt;");
                case '&' -> out.write("&amp;");
                case '\r' -> out.write("&#13;");
                default -> out.write(c);
            }
        }
    }
}
