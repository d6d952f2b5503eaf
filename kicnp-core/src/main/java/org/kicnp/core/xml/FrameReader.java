package org.kicnp.core.xml;

import com.ctc.wstx.exc.WstxLazyException;
import java.io.CharConversionException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Optional;
import java.util.function.Consumer;
import javax.xml.stream.Location;
import javax.xml.stream.XMLStreamConstants;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamReader;

/**
 * Reads one knowledge document with StAX into {@link FrameElement}s, handing each to a sink as soon as its FRAME
 * element ends, so a large file is never held as a tree. Structural mistakes (unknown or repeated elements, stray
 * text, attributes) are collected with their location and reading goes on; malformed XML ends the document.
 */
final class FrameReader {
    private final XMLStreamReader r;
    private final String source;
    private final List<LoadError> errors;
    private final Consumer<FrameElement> sink;
    private final TextCache texts = new TextCache();
    /** Whether reading stopped before the end of the document or skipped a FRAME, so frames were never seen. */
    private boolean cut;
    /** The NAME of the frame and of the slot being read, once read: what malformed XML found there is about. */
    private String frameName;
    private String slotName;

    private FrameReader(XMLStreamReader r, String source, List<LoadError> errors, Consumer<FrameElement> sink) {
        this.r = r;
        this.source = source;
        this.errors = errors;
        this.sink = sink;
    }

    /**
     * Reads the document, adding what is wrong to {@code errors} and every readable frame to {@code sink}.
     *
     * @return whether the whole document was read: false when malformed XML, a DTD or a root element that is not
     *     KNOWLEDGEBASE or FRAME stopped the reading, or a FRAME in the wrong place was skipped, so frames it holds
     *     may be missing
     */
    static boolean read(XMLStreamReader reader, String source, List<LoadError> errors, Consumer<FrameElement> sink) {
        return read(reader, source, errors, sink, Optional.empty());
    }

    /**
     * As {@link #read(XMLStreamReader, String, List, Consumer)}, for the document in {@code file}: a byte that is not
     * UTF-8 is then reported where it is in the file, which the parser, decoding ahead, cannot say.
     */
    static boolean read(XMLStreamReader reader, String source, List<LoadError> errors, Consumer<FrameElement> sink,
            Optional<Path> file) {
        FrameReader fr = new FrameReader(reader, source, errors, sink);
        try {
            fr.document();
            return !fr.cut;
        } catch (XMLStreamException e) {
            fr.malformed(e, file);
            return false;
        } catch (WstxLazyException e) {
            // A mistake inside text the parser had begun (a bare '&' in a script, text over the size limit) comes
            // when the text is asked for, unchecked: it is malformed XML all the same.
            fr.malformed(e.getCause() instanceof XMLStreamException x ? x : new XMLStreamException(e.getMessage()),
                    file);
            return false;
        } finally {
            try {
                reader.close();
            } catch (XMLStreamException ignored) {
                // Nothing useful to report: the document has been read or has already failed.
            }
        }
    }

    private void document() throws XMLStreamException {
        boolean sawRoot = false;
        while (r.hasNext()) {
            int event = r.next();
            switch (event) {
                case XMLStreamConstants.DTD -> {
                    error(r.getLocation(), "DTDs are not allowed in knowledge files; remove the DOCTYPE declaration.");
                    cut = true;
                    return;
                }
                case XMLStreamConstants.START_ELEMENT -> {
                    sawRoot = true;
                    root();
                }
                default -> { }
            }
        }
        if (!sawRoot) {
            errors.add(new LoadError(source, 1, 1, "The document has no root element; expected KNOWLEDGEBASE or FRAME."));
        }
    }

    private void root() throws XMLStreamException {
        String tag = r.getLocalName();
        checkRootAttributes();
        switch (tag) {
            case "KNOWLEDGEBASE" -> {
                while (nextChild("KNOWLEDGEBASE")) {
                    if (r.getLocalName().equals("FRAME")) {
                        noAttributes();
                        sink.accept(frame());
                    } else {
                        unknown("KNOWLEDGEBASE", "FRAME");
                    }
                }
            }
            case "FRAME" -> sink.accept(frame());
            default -> {
                error(r.getLocation(), "The root element is '" + tag + "'; a knowledge file holds KNOWLEDGEBASE or "
                        + "a single FRAME.");
                cut = true;
                skip();
            }
        }
    }

    private FrameElement frame() throws XMLStreamException {
        SourceLocation at = here();
        int errorsBefore = errors.size();
        EnumMap<FrameTag, Located> items = new EnumMap<>(FrameTag.class);
        List<LinkElement> to = new ArrayList<>(0);
        List<LinkElement> from = new ArrayList<>(0);
        List<SlotElement> slots = new ArrayList<>(8);
        boolean slotList = false;
        boolean sawTo = false;
        boolean sawFrom = false;
        while (nextChild("FRAME")) {
            String tag = r.getLocalName();
            noAttributes();
            switch (tag) {
                case "SLOTLIST" -> {
                    if (slotList) {
                        repeated("FRAME", tag);
                    } else {
                        slotList = true;
                        slotList(slots);
                    }
                }
                case "SEMANTICLINKTO" -> {
                    if (sawTo) {
                        repeated("FRAME", tag);
                    } else {
                        sawTo = true;
                        links(tag, to);
                    }
                }
                case "SEMANTICLINKFROM" -> {
                    if (sawFrom) {
                        repeated("FRAME", tag);
                    } else {
                        sawFrom = true;
                        links(tag, from);
                    }
                }
                default -> {
                    FrameTag t = FrameTag.of(tag);
                    if (t == null) {
                        unknown("FRAME", "NAME, ISA, ISINSTANCE, DESCENDANTS, HASPART, SEMANTICLINKTO, "
                                + "SEMANTICLINKFROM, LEARNED, RUNTIME, PRIORITY or SLOTLIST");
                    } else if (items.containsKey(t)) {
                        repeated("FRAME", tag);
                    } else {
                        Located item = leaf(tag, t.childTags());
                        items.put(t, item);
                        if (t == FrameTag.NAME && !item.absent()) {
                            frameName = item.stripped();
                        }
                    }
                }
            }
        }
        frameName = null;
        concern(errorsBefore, items.get(FrameTag.NAME), false);
        return new FrameElement(at, items, to, from, slots, errors.size() > errorsBefore);
    }

    /**
     * Marks the errors found since {@code from} as concerning the frame (or slot) just read, when its NAME, which may
     * come after the mistake, says which: the editor shows each error at its frame and slot.
     */
    private void concern(int from, Located name, boolean slot) {
        if (name == null || name.absent()) {
            return;
        }
        Optional<String> named = Optional.of(name.stripped());
        for (int i = from; i < errors.size(); i++) {
            LoadError e = errors.get(i);
            if (slot ? e.slot().isEmpty() : e.frame().isEmpty()) {
                errors.set(i, new LoadError(e.source(), e.line(), e.column(), e.message(), slot ? e.frame() : named,
                        slot ? named : e.slot()));
            }
        }
    }

    private void slotList(List<SlotElement> slots) throws XMLStreamException {
        while (nextChild("SLOTLIST")) {
            noAttributes();
            if (r.getLocalName().equals("SLOT")) {
                slots.add(slot());
            } else {
                unknown("SLOTLIST", "SLOT");
            }
        }
    }

    private SlotElement slot() throws XMLStreamException {
        Location start = r.getLocation();
        int errorsBefore = errors.size();
        Located[] facets = new Located[SlotTag.COUNT];
        while (nextChild("SLOT")) {
            String tag = r.getLocalName();
            noAttributes();
            SlotTag t = SlotTag.of(tag);
            if (t == null) {
                unknown("SLOT", "NAME, TYPE, CONDITION, ARGUMENT, VALUE, DEFAULT, REQUIRED, SHARED, UNIQUE, ROLE, "
                        + "FROM, FRAMERELATED, FRAMELISTRELATED, ONNEEDED, ONADDED, ONREMOVED or REACTIVE");
            } else if (facets[t.ordinal()] != null) {
                repeated("SLOT", tag);
            } else {
                facets[t.ordinal()] = leaf(tag, t.childTags());
                if (t == SlotTag.NAME && !facets[t.ordinal()].absent()) {
                    slotName = facets[t.ordinal()].stripped();
                }
            }
        }
        slotName = null;
        concern(errorsBefore, facets[SlotTag.NAME.ordinal()], true);
        return new SlotElement(start.getLineNumber(), start.getColumnNumber(), facets);
    }

    private void links(String list, List<LinkElement> out) throws XMLStreamException {
        while (nextChild(list)) {
            noAttributes();
            if (!r.getLocalName().equals("LINK")) {
                unknown(list, "LINK");
                continue;
            }
            Location start = r.getLocation();
            Located relation = null;
            Located target = null;
            while (nextChild("LINK")) {
                String tag = r.getLocalName();
                noAttributes();
                if (tag.equals("RELATION") && relation == null) {
                    relation = leaf(tag, List.of());
                } else if (tag.equals("TARGET") && target == null) {
                    target = leaf(tag, List.of());
                } else if (tag.equals("RELATION") || tag.equals("TARGET")) {
                    repeated("LINK", tag);
                } else {
                    unknown("LINK", "RELATION and TARGET");
                }
            }
            out.add(new LinkElement(start.getLineNumber(), start.getColumnNumber(),
                    java.util.Optional.ofNullable(relation), java.util.Optional.ofNullable(target)));
        }
    }

    /** Reads a simple element: text, or (where {@code childTags} allows) child elements that hold text. */
    private Located leaf(String tag, List<String> childTags) throws XMLStreamException {
        Location start = r.getLocation();
        String text = "";
        StringBuilder more = null;
        int textLine = -1;
        int textColumn = -1;
        boolean literal = false;
        List<Located> items = List.of();
        while (true) {
            int event = r.next();
            switch (event) {
                case XMLStreamConstants.CHARACTERS, XMLStreamConstants.CDATA, XMLStreamConstants.SPACE -> {
                    literal |= event == XMLStreamConstants.CDATA;
                    if (textLine < 0) {
                        // Only a condition's errors point inside its text; other elements skip the location.
                        if (tag.equals("CONDITION")) {
                            Location l = r.getLocation();
                            textLine = l.getLineNumber();
                            textColumn = l.getColumnNumber();
                        } else {
                            textLine = 0;
                        }
                        text = event == XMLStreamConstants.CHARACTERS
                                ? texts.text(r.getTextCharacters(), r.getTextStart(), r.getTextLength()) : r.getText();
                    } else {
                        // Text beside ITEM children is reported below unless it is white space; none is dropped
                        // here, so white space between comments and further text stays part of the text.
                        if (more == null) {
                            more = new StringBuilder(text);
                        }
                        more.append(r.getTextCharacters(), r.getTextStart(), r.getTextLength());
                    }
                }
                case XMLStreamConstants.START_ELEMENT -> {
                    String child = r.getLocalName();
                    noAttributes();
                    if (childTags.contains(child)) {
                        if (items.isEmpty()) {
                            items = new ArrayList<>();
                        }
                        // An ITEM of a slot's VALUE or DEFAULT may hold ITEMs itself: a list inside a list.
                        boolean nests = child.equals("ITEM") && (tag.equals("VALUE") || tag.equals("DEFAULT")
                                || tag.equals("ITEM"));
                        items.add(leaf(child, nests ? List.of("ITEM") : List.of()));
                    } else {
                        unknown(tag, childTags.isEmpty() ? "text only" : String.join(" or ", childTags));
                    }
                }
                case XMLStreamConstants.END_ELEMENT -> {
                    if (more != null) {
                        text = more.toString();
                        // The parser limits each piece of text; pieces split by comments or CDATA are checked here.
                        if (text.length() > SecureXml.MAX_TEXT) {
                            error(start, "Element " + tag + " holds " + text.length() + " characters of text, more "
                                    + "than the " + SecureXml.MAX_TEXT + " a knowledge file may hold in one element.");
                        }
                    }
                    if (!items.isEmpty() && !text.isBlank()) {
                        error(start, "Element " + tag + " mixes text with " + String.join("/", childTags)
                                + " elements; give one or the other.");
                    }
                    return new Located(text, items, start.getLineNumber(), start.getColumnNumber(),
                            textLine <= 0 ? start.getLineNumber() : textLine, textLine <= 0 ? 0 : textColumn, literal);
                }
                default -> { }
            }
        }
    }

    /** Moves to the next child element of {@code parent}; false at its end. Reports stray text other than NULL. */
    private boolean nextChild(String parent) throws XMLStreamException {
        while (true) {
            int event = r.next();
            switch (event) {
                case XMLStreamConstants.START_ELEMENT -> {
                    return true;
                }
                case XMLStreamConstants.END_ELEMENT -> {
                    return false;
                }
                case XMLStreamConstants.CHARACTERS, XMLStreamConstants.CDATA -> {
                    if (r.isWhiteSpace()) {
                        // Indentation: Woodstox knows it is blank without building a String for it.
                        continue;
                    }
                    String t = r.getText().strip();
                    if (!t.isEmpty() && !Located.isNull(t)) {
                        error(r.getLocation(), "Text '" + abbreviate(t) + "' is not allowed directly inside "
                                + parent + ".");
                    }
                }
                default -> { }
            }
        }
    }

    private void unknown(String parent, String expected) throws XMLStreamException {
        error(r.getLocation(), "Unknown element '" + r.getLocalName() + "' in " + parent + "; expected " + expected
                + ".");
        skip();
    }

    private void repeated(String parent, String tag) throws XMLStreamException {
        error(r.getLocation(), parent + " has more than one " + tag + " element; give it once.");
        skip();
    }

    /**
     * Skips the current element and everything inside it. A FRAME skipped this way (one put inside another, say)
     * is a frame never read, so the document counts as not read whole.
     */
    private void skip() throws XMLStreamException {
        if (r.getLocalName().equals("FRAME")) {
            cut = true;
        }
        int depth = 1;
        while (depth > 0) {
            int event = r.next();
            if (event == XMLStreamConstants.START_ELEMENT) {
                depth++;
                if (r.getLocalName().equals("FRAME")) {
                    cut = true;
                }
            } else if (event == XMLStreamConstants.END_ELEMENT) {
                depth--;
            }
        }
    }

    private void noAttributes() {
        if (r.getAttributeCount() > 0) {
            error(r.getLocation(), "Element " + r.getLocalName() + " has attribute '" + r.getAttributeLocalName(0)
                    + "'; the format uses elements only.");
        }
    }

    private void checkRootAttributes() {
        for (int i = 0; i < r.getAttributeCount(); i++) {
            String name = r.getAttributeLocalName(i);
            if (!name.startsWith("xmlns") && !name.startsWith("xsi:")) {
                error(r.getLocation(), "Element " + r.getLocalName() + " has attribute '" + name
                        + "'; only xmlns and xsi: schema attributes are allowed on the root.");
            }
        }
    }

    private SourceLocation here() {
        Location l = r.getLocation();
        return new SourceLocation(source, l.getLineNumber(), l.getColumnNumber());
    }

    private void error(Location l, String message) {
        errors.add(new LoadError(source, l.getLineNumber(), l.getColumnNumber(), message));
    }

    private void malformed(XMLStreamException e, Optional<Path> file) {
        errors.add(file.filter(f -> notUtf8(e)).flatMap(f -> Utf8Check.firstMalformed(f, source))
                .orElseGet(() -> syntaxError(e)));
    }

    /** Whether the parser stopped at bytes that do not decode as UTF-8 (Woodstox wraps its decoder's exception). */
    private static boolean notUtf8(XMLStreamException e) {
        Throwable t = e;
        for (int depth = 0; t != null && depth < 8; depth++) {
            if (t instanceof CharConversionException && String.valueOf(t.getMessage()).contains("UTF-8")) {
                return true;
            }
            t = t.getCause() == null && t instanceof XMLStreamException x ? x.getNestedException() : t.getCause();
        }
        return false;
    }

    private LoadError syntaxError(XMLStreamException e) {
        Location l = e.getLocation() != null ? e.getLocation() : r.getLocation();
        String msg = e.getMessage() == null ? "unreadable XML" : e.getMessage();
        int cut = msg.indexOf("\n at [");
        if (cut >= 0) {
            msg = msg.substring(0, cut);
        }
        msg = msg.strip();
        if (msg.startsWith("ParseError at [")) {
            int m = msg.indexOf("Message: ");
            msg = m >= 0 ? msg.substring(m + 9) : msg;
        }
        if (!msg.endsWith(".")) {
            msg = msg + ".";
        }
        return new LoadError(source, l == null ? 1 : Math.max(1, l.getLineNumber()),
                l == null ? 1 : Math.max(1, l.getColumnNumber()), "The XML is not well-formed: " + msg,
                Optional.ofNullable(frameName), Optional.ofNullable(slotName));
    }

    private static String abbreviate(String t) {
        return t.length() <= 40 ? t : t.substring(0, 37) + "...";
    }
}
