package org.kicnp.core.xml;

import static java.util.Objects.requireNonNull;

import java.io.OutputStreamWriter;
import java.io.IOException;
import java.io.StringWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.List;
import org.kicnp.core.Condition;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeException;
import org.kicnp.core.SemanticLink;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

/**
 * Writes frames in the paper's XML format (Table 4). Deterministic: the same frames give byte-identical output
 * (UTF-8, two-space indentation, {@code \n} line ends). REQUIRED, SHARED and UNIQUE are always written on a class
 * frame's slots, as the paper does, and on an instance's slots only when they differ from their defaults; every other
 * facet only when it differs from its default. DESCENDANTS are derived and never written. Frames
 * of {@link org.kicnp.core.Provenance#RUNTIME} provenance are written like declared frames.
 */
public final class KnowledgeXmlWriter {
    private static final String HEADER = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    /** How deep lists may nest in a value (a list of lists is 2). */
    static final int MAX_NESTED_LISTS = 16;
    private static final String[] INDENT = new String[12];

    static {
        for (int i = 0; i < INDENT.length; i++) {
            INDENT[i] = "  ".repeat(i);
        }
    }

    private final CharSink out;

    private KnowledgeXmlWriter(CharSink out) {
        this.out = out;
    }

    /**
     * Writes a KNOWLEDGEBASE document holding the frames in the given order; flushes but does not close.
     *
     * @throws KnowledgeException when the writer fails, or a frame holds what XML cannot (lists nested more than
     *     {@value #MAX_NESTED_LISTS} deep, a character such as U+0007)
     */
    public static void write(List<Frame> frames, Writer out) {
        requireNonNull(frames, "frames");
        requireNonNull(out, "out");
        try {
            CharSink sink = new CharSink(out);
            KnowledgeXmlWriter x = new KnowledgeXmlWriter(sink);
            sink.write(HEADER);
            sink.write("<KNOWLEDGEBASE>\n");
            for (Frame f : frames) {
                x.frame(f, 1);
            }
            sink.write("</KNOWLEDGEBASE>\n");
            sink.flush();
        } catch (IOException e) {
            throw new KnowledgeException("Writing frames as XML failed: " + e.getMessage(), e);
        }
    }

    /**
     * Writes a KNOWLEDGEBASE file (UTF-8), replacing it atomically: readers see the old file or the whole new one.
     *
     * @throws KnowledgeException when the file cannot be written, or a frame holds what XML cannot
     */
    public static void write(List<Frame> frames, Path file) {
        requireNonNull(file, "file");
        Path abs = file.toAbsolutePath();
        Path tmp = abs.resolveSibling("." + abs.getFileName() + ".tmp");
        try {
            try (Writer w = new OutputStreamWriter(Files.newOutputStream(tmp), StandardCharsets.UTF_8)) {
                write(frames, w);
            }
            try {
                Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            } catch (java.nio.file.AtomicMoveNotSupportedException e) {
                Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING);
            }
        } catch (IOException e) {
            throw new KnowledgeException("Frames could not be written to '" + file + "': " + e.getMessage(), e);
        } finally {
            try {
                Files.deleteIfExists(tmp);
            } catch (IOException ignored) {
                // The temporary file is hidden and rewritten by the next save.
            }
        }
    }

    /**
     * A document whose root is the single FRAME element, as the paper prints one.
     *
     * @throws KnowledgeException when the frame holds what XML cannot
     */
    public static String toXml(Frame frame) {
        requireNonNull(frame, "frame");
        StringWriter sw = new StringWriter(1024);
        try {
            CharSink sink = new CharSink(sw);
            sink.write(HEADER);
            new KnowledgeXmlWriter(sink).frame(frame, 0);
            sink.flush();
        } catch (IOException e) {
            throw new KnowledgeException("Writing frame '" + frame.name() + "' as XML failed: " + e.getMessage(), e);
        }
        return sw.toString();
    }

    private void frame(Frame f, int d) throws IOException {
        open("FRAME", d);
        name(f.name(), d + 1);
        if (f.parent().isPresent()) {
            text("ISA", f.parent().get(), d + 1, "frame '" + f.name() + "'");
        }
        element("ISINSTANCE", f.isInstance() ? "TRUE" : "FALSE", d + 1);
        if (f.learned()) {
            element("LEARNED", "TRUE", d + 1);
        }
        if (f.priority() != 0) {
            element("PRIORITY", Integer.toString(f.priority()), d + 1);
        }
        if (!f.parts().isEmpty()) {
            open("HASPART", d + 1);
            for (String p : f.parts()) {
                text("PART", p, d + 2, "frame '" + f.name() + "'");
            }
            close("HASPART", d + 1);
        }
        links("SEMANTICLINKTO", f, f.linksTo(), d + 1);
        links("SEMANTICLINKFROM", f, f.linksFrom(), d + 1);
        if (!f.slots().isEmpty()) {
            open("SLOTLIST", d + 1);
            for (Slot s : f.slots()) {
                slot(f, s, d + 2);
            }
            close("SLOTLIST", d + 1);
        }
        close("FRAME", d);
    }

    private void links(String tag, Frame f, List<SemanticLink> links, int d) throws IOException {
        if (links.isEmpty()) {
            return;
        }
        open(tag, d);
        for (SemanticLink l : links) {
            open("LINK", d + 1);
            text("RELATION", l.relation().name(), d + 2, "frame '" + f.name() + "'");
            text("TARGET", l.frame(), d + 2, "frame '" + f.name() + "'");
            close("LINK", d + 1);
        }
        close(tag, d);
    }

    private void slot(Frame f, Slot s, int d) throws IOException {
        String where = "slot '" + s.name() + "' of frame '" + f.name() + "'";
        open("SLOT", d);
        name(s.name(), d + 1);
        element("TYPE", s.type().xmlName(), d + 1);
        if (!(s.condition() instanceof Condition.Any)) {
            text("CONDITION", s.condition().text(), d + 1, where);
        }
        if (s.argument().isPresent()) {
            text("ARGUMENT", s.argument().get(), d + 1, where);
        }
        if (s.value().isPresent()) {
            value("VALUE", s.value().get(), d + 1, where);
        }
        if (s.defaultValue().isPresent()) {
            value("DEFAULT", s.defaultValue().get(), d + 1, where);
        }
        // A class declares the flags, so its slots always carry them, as in the paper. An instance's slot takes them
        // from its class, so there each is written only when it differs from its default: in a large knowledge
        // base, mostly instances, that is a third of the file's elements saved on every load and save.
        boolean declaring = f.isClass();
        if (declaring || s.required()) {
            element("REQUIRED", s.required() ? "TRUE" : "FALSE", d + 1);
        }
        if (declaring || !s.shared()) {
            element("SHARED", s.shared() ? "TRUE" : "FALSE", d + 1);
        }
        if (declaring || s.unique()) {
            element("UNIQUE", s.unique() ? "TRUE" : "FALSE", d + 1);
        }
        if (s.role().isPresent()) {
            text("ROLE", s.role().get(), d + 1, where);
        }
        if (s.from().isPresent()) {
            text("FROM", s.from().get(), d + 1, where);
        }
        if (s.frameRelated().isPresent()) {
            text("FRAMERELATED", s.frameRelated().get(), d + 1, where);
        }
        if (!s.frameListRelated().isEmpty()) {
            open("FRAMELISTRELATED", d + 1);
            for (String r : s.frameListRelated()) {
                text("ITEM", r, d + 2, where);
            }
            close("FRAMELISTRELATED", d + 1);
        }
        if (s.onNeeded().isPresent()) {
            text("ONNEEDED", s.onNeeded().get(), d + 1, where);
        }
        if (s.onAdded().isPresent()) {
            text("ONADDED", s.onAdded().get(), d + 1, where);
        }
        if (s.onRemoved().isPresent()) {
            text("ONREMOVED", s.onRemoved().get(), d + 1, where);
        }
        if (!s.reactive()) {
            element("REACTIVE", "FALSE", d + 1);
        }
        close("SLOT", d);
    }

    private void value(String tag, Value v, int d, String where) throws IOException {
        if (!(v instanceof Value.Lst list)) {
            text(tag, v.text(), d, where);
            return;
        }
        if (list.items().isEmpty()) {
            element(tag, "[]", d);
            return;
        }
        open(tag, d);
        for (Value item : list.items()) {
            item(item, d + 1, 1, where);
        }
        close(tag, d);
    }

    /**
     * One ITEM of a list: a list inside it as ITEMs inside the ITEM ({@code []} for the empty list), so the text
     * {@code []} itself goes in CDATA; at most {@link #MAX_NESTED_LISTS} lists deep, well within the reader's limit
     * on element depth.
     */
    private void item(Value item, int d, int nesting, String where) throws IOException {
        if (item instanceof Value.Lst inner) {
            if (nesting >= MAX_NESTED_LISTS) {
                throw new KnowledgeException("The " + where + " holds lists nested more than " + MAX_NESTED_LISTS
                        + " deep, which the XML format cannot write.");
            }
            if (inner.items().isEmpty()) {
                element("ITEM", "[]", d);
                return;
            }
            open("ITEM", d);
            for (Value i : inner.items()) {
                item(i, d + 1, nesting + 1, where);
            }
            close("ITEM", d);
        } else if (item instanceof Value.Str str && str.text().strip().equals("[]")) {
            indent(d);
            out.write("<ITEM><![CDATA[" + str.text() + "]]></ITEM>\n"); // text, not the empty list
        } else {
            text("ITEM", item.text(), d, where);
        }
    }

    private void open(String tag, int d) throws IOException {
        indent(d);
        out.write('<');
        out.write(tag);
        out.write(">\n");
    }

    private void close(String tag, int d) throws IOException {
        indent(d);
        out.write("</");
        out.write(tag);
        out.write(">\n");
    }

    /** An element whose text is known to need no escaping (names checked by the frame model, keywords, numbers). */
    private void element(String tag, String text, int d) throws IOException {
        indent(d);
        out.write('<');
        out.write(tag);
        out.write('>');
        out.write(text);
        out.write("</");
        out.write(tag);
        out.write(">\n");
    }

    /** A frame or slot NAME: checked by the frame model, so it needs no escaping, but NULL must not read as absent. */
    private void name(String name, int d) throws IOException {
        if (Located.isNull(name)) {
            text("NAME", name, d, "name '" + name + "'");
        } else {
            element("NAME", name, d);
        }
    }

    /** An element holding free text: escaped, or in CDATA when it holds markup characters or line breaks. */
    private void text(String tag, String text, int d, String where) throws IOException {
        indent(d);
        out.write('<');
        out.write(tag);
        out.write('>');
        XmlText.write(out, text, where);
        out.write("</");
        out.write(tag);
        out.write(">\n");
    }

    private void indent(int d) throws IOException {
        out.write(d < INDENT.length ? INDENT[d] : "  ".repeat(d));
    }
}
