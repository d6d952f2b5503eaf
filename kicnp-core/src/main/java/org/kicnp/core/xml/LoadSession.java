package org.kicnp.core.xml;

import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Comparator;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.Consumer;
import java.util.function.Function;
import javax.xml.stream.XMLInputFactory;
import javax.xml.stream.XMLStreamException;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Problem;
import org.kicnp.core.Slot;
import org.kicnp.core.StagedBatch;

/**
 * The state of one load: documents are read one after another and each frame is mapped as soon as it is read, unless
 * one of its slots leaves out its TYPE; those frames wait until every document is read, because the declaration they
 * inherit the type from may come later. Frame names are checked for duplicates across all documents.
 *
 * <p>When some frames cannot be read or mapped, a load still checks the frames that did map against the frame model
 * and reports those problems together with the errors in the XML, so one round of fixes finds them all. Problems
 * that may only follow from a frame that failed (one that names it, or a frame below it, whose inherited slots are
 * unknown) are left out, and so is the whole check when a document could not be read to its end.
 */
final class LoadSession {
    /** Frames handed to a load's staged batch at a time. */
    private static final int STREAM_CHUNK = 512;

    private final KnowledgeBase context;
    /** The frames above those read, by name: the context's, unless the caller reads against another state. */
    private final Function<String, Optional<Frame>> above;
    private final XMLInputFactory factory = SecureXml.inputFactory();
    private final long maxBytes = SecureXml.maxFileBytes();
    /** Errors found while mapping (on the mapping thread when there is one) and after. */
    private final List<LoadError> errors = new ArrayList<>();
    /** Errors found while reading, always on the calling thread. */
    private final List<LoadError> readErrors = new ArrayList<>();
    private final List<String> sources = new ArrayList<>();
    private final Consumer<FrameElement> sink;
    private final MappingPipeline pipeline;
    private final Interner interner = new Interner();
    private final FrameMapper mapper = new FrameMapper(interner, new FrameMapper.TypeLookup() {
        @Override public Optional<DataType> declaredType(String frame, String slot) {
            return LoadSession.this.declaredType(frame, slot);
        }

        @Override public Optional<String> declaredArgument(String frame, String slot) {
            return LoadSession.this.declaredArgument(frame, slot);
        }
    }, errors);
    private final List<ParsedFrame> parsed = new ArrayList<>();
    private final List<FrameElement> pending = new ArrayList<>();
    private final List<Integer> pendingSlots = new ArrayList<>();
    private final Map<String, Frame> byName = new HashMap<>();
    private final Map<String, FrameElement> unmapped = new HashMap<>();
    private final Map<String, SourceLocation> seen = new HashMap<>(1 << 12);
    private final Map<String, Located> descendants = new HashMap<>();
    /** Names of frames that were read but could not be mapped, or were read with structural mistakes. */
    private final Set<String> failed = new HashSet<>();
    /** Whether every document was read to its end (false: frames of a document may be missing altogether). */
    private boolean whole = true;
    /** Where mapped frames go as soon as they are mapped, for a load; null when only parsing. */
    private final StagedBatch target;
    /** The knowledge base's problems with a batch of adds, for a load; null when only parsing. */
    private final Function<List<Frame>, List<Problem>> check;
    /** Frames of {@code parsed} before this index have been given to {@code target}. */
    private int streamed;

    /**
     * @param pipelined whether to map frames on a second thread while reading, worth it for large inputs only
     * @param target the batch of a load, which gets the mapped frames in file order as they are mapped (so the
     *     knowledge base checks them while reading goes on), or null
     */
    LoadSession(KnowledgeBase context, boolean pipelined, StagedBatch target) {
        this(context, pipelined, target, null);
    }

    /**
     * @param check for a load, the problems the knowledge base finds with adding frames, so that when some frames
     *     fail to map the others are still checked and their problems reported with the errors; null when parsing
     */
    LoadSession(KnowledgeBase context, boolean pipelined, StagedBatch target,
            Function<List<Frame>, List<Problem>> check) {
        this(context, context::frame, pipelined, target, check);
    }

    /**
     * @param above where the declarations of frames not read are looked up, instead of {@code context}: for text
     *     written against a state the knowledge base does not hold (yet), such as a journal record replayed later
     */
    LoadSession(KnowledgeBase context, Function<String, Optional<Frame>> above, boolean pipelined, StagedBatch target,
            Function<List<Frame>, List<Problem>> check) {
        this.context = context;
        this.above = above;
        this.target = target;
        this.check = check;
        this.pipeline = pipelined ? new MappingPipeline(this::accept) : null;
        this.sink = pipelined ? pipeline : this::accept;
    }

    /** Stops a mapping thread if the load ends early. */
    void abandon() {
        if (pipeline != null) {
            pipeline.abandon();
        }
    }

    void readFile(Path file) {
        String source = file.toString();
        sources.add(source);
        try {
            long size = Files.size(file);
            if (size > maxBytes) {
                readErrors.add(new LoadError(source, 1, 1, "The file is " + size + " bytes, more than the limit of "
                        + maxBytes + " bytes (system property " + SecureXml.MAX_BYTES_PROPERTY + ")."));
                whole = false;
                return;
            }
            // 64 K reads instead of the parser's 4 K ones: fewer trips through the channel's temporary buffers.
            try (InputStream in = new BufferedInputStream(Files.newInputStream(file), 1 << 16)) {
                if (!FrameReader.read(factory.createXMLStreamReader(source, in), source, readErrors, sink,
                        Optional.of(file))) {
                    whole = false;
                }
            }
        } catch (IOException e) {
            readErrors.add(new LoadError(source, 1, 1, "The file cannot be read: " + e.getMessage() + "."));
            whole = false;
        } catch (XMLStreamException e) {
            readErrors.add(new LoadError(source, 1, 1, "The file cannot be read as XML: " + e.getMessage()));
            whole = false;
        }
    }

    void readText(String xml, String source) {
        sources.add(source);
        if (xml.length() > maxBytes) {
            readErrors.add(new LoadError(source, 1, 1, "The text is " + xml.length() + " characters, more than the limit of "
                    + maxBytes + " (system property " + SecureXml.MAX_BYTES_PROPERTY + ")."));
            whole = false;
            return;
        }
        try {
            if (!FrameReader.read(factory.createXMLStreamReader(new StringReader(xml)), source, readErrors, sink)) {
                whole = false;
            }
        } catch (XMLStreamException e) {
            readErrors.add(new LoadError(source, 1, 1, "The text cannot be read as XML: " + e.getMessage()));
            whole = false;
        }
    }

    private void accept(FrameElement e) {
        Optional<String> name = e.name();
        if (name.isPresent()) {
            SourceLocation first = seen.putIfAbsent(name.get(), e.location());
            if (first != null) {
                errors.add(LoadError.at(e.location(), "Frame '" + name.get() + "' is defined twice: here and at "
                        + first + ".", name.get(), null));
                return;
            }
            e.present(FrameTag.DESCENDANTS).ifPresent(d -> descendants.put(name.get(), d));
            if (e.damaged()) {
                failed.add(name.get());
            }
        }
        if (e.selfTyped()) {
            Optional<Frame> mapped = mapper.map(e);
            mapped.ifPresent(f -> add(f, e));
            if (mapped.isEmpty()) {
                // Its error is reported; the slot types it declares still serve the frames below it, which would
                // otherwise each report "no frame above it declares" a slot that it does declare.
                name.ifPresent(n -> {
                    unmapped.put(n, e);
                    failed.add(n);
                });
            }
        } else {
            name.ifPresent(n -> unmapped.put(n, e));
            pending.add(e);
            pendingSlots.add(parsed.size());
            parsed.add(null);
        }
    }

    private void add(Frame f, FrameElement e) {
        parsed.add(located(f, e));
        if (target != null && pending.isEmpty() && parsed.size() - streamed >= STREAM_CHUNK) {
            stream();
        }
    }

    /**
     * Gives the target the frames mapped since the last time. Stops for good at a frame that waits for its slot
     * types (mapped only at the end), so the target sees the frames in file order.
     */
    private void stream() {
        List<Frame> frames = new ArrayList<>(parsed.size() - streamed);
        for (int i = streamed; i < parsed.size(); i++) {
            ParsedFrame p = parsed.get(i);
            if (p == null) {
                break;
            }
            frames.add(p.sourced().frame());
        }
        streamed += frames.size();
        if (!frames.isEmpty()) {
            target.add(frames);
        }
    }

    /** Maps the frames that waited for their slot types, checks DESCENDANTS, and answers every frame in file order. */
    List<ParsedFrame> finish() {
        if (pipeline != null) {
            pipeline.finish();
        }
        if (!pending.isEmpty()) {
            for (ParsedFrame p : parsed) {
                if (p != null) {
                    byName.put(p.sourced().frame().name(), p.sourced().frame());
                }
            }
        }
        for (int i = 0; i < pending.size(); i++) {
            FrameElement e = pending.get(i);
            int index = pendingSlots.get(i);
            Optional<Frame> mapped = mapper.map(e);
            mapped.ifPresent(f -> {
                byName.put(f.name(), f);
                parsed.set(index, located(f, e));
            });
            if (mapped.isEmpty()) {
                e.name().ifPresent(failed::add);
            }
        }
        descendants.forEach(this::checkDescendants);
        if (!errors.isEmpty() || !readErrors.isEmpty()) {
            if (check != null && whole) {
                errors.addAll(problemsOfTheRest());
            }
            List<SourcedFrame> read = new ArrayList<>(parsed.size());
            for (ParsedFrame p : parsed) {
                if (p != null && !failed.contains(p.sourced().frame().name())) {
                    read.add(p.sourced());
                }
            }
            throw new KnowledgeXmlException(inDocumentOrder(), read);
        }
        if (target != null) {
            stream();
        }
        return parsed;
    }

    /**
     * The frame-model problems of the frames that did map, as a load of them alone would report them, placed at their
     * elements; without those that may only follow from a frame that failed: about a frame that failed or lies below
     * one, or naming such a frame.
     */
    private List<LoadError> problemsOfTheRest() {
        Map<String, ParsedFrame> good = new LinkedHashMap<>();
        for (ParsedFrame p : parsed) {
            if (p != null && !failed.contains(p.sourced().frame().name())) {
                good.putIfAbsent(p.sourced().frame().name(), p);
            }
        }
        if (good.isEmpty()) {
            return List.of();
        }
        List<Frame> frames = new ArrayList<>(good.size());
        good.values().forEach(p -> frames.add(p.sourced().frame()));
        Set<String> tainted = new HashSet<>(failed);
        for (Frame f : frames) {
            if (belowFailed(f, good)) {
                tainted.add(f.name());
            }
        }
        List<LoadError> out = new ArrayList<>();
        for (Problem p : check.apply(frames)) {
            if (!tainted.contains(p.frame()) && !namesAny(p.message(), tainted)) {
                out.add(KnowledgeLoader.locate(p, good.get(p.frame())));
            }
        }
        return out;
    }

    /** Whether a frame that failed is on {@code f}'s IS-A chain, among the frames read and then the context. */
    private boolean belowFailed(Frame f, Map<String, ParsedFrame> good) {
        Set<String> visited = new HashSet<>();
        String p = f.parent().orElse(null);
        while (p != null && visited.add(p)) {
            if (failed.contains(p)) {
                return true;
            }
            ParsedFrame read = good.get(p);
            Frame up = read != null ? read.sourced().frame() : above.apply(p).orElse(null);
            p = up == null ? null : up.parent().orElse(null);
        }
        return false;
    }

    /** Whether the message quotes ('like this') one of the names. */
    private static boolean namesAny(String message, Set<String> names) {
        int open = message.indexOf('\'');
        while (open >= 0) {
            int close = message.indexOf('\'', open + 1);
            if (close < 0) {
                return false;
            }
            if (names.contains(message.substring(open + 1, close))) {
                return true;
            }
            open = close;
        }
        return false;
    }

    /** All errors by file (in reading order), line and column, whichever thread found them. */
    private List<LoadError> inDocumentOrder() {
        Map<String, Integer> order = new HashMap<>();
        for (String s : sources) {
            order.putIfAbsent(s, order.size());
        }
        List<LoadError> all = new ArrayList<>(readErrors.size() + errors.size());
        all.addAll(readErrors);
        all.addAll(errors);
        all.sort(Comparator.comparingInt((LoadError e) -> order.getOrDefault(e.source(), Integer.MAX_VALUE))
                .thenComparingInt(LoadError::line).thenComparingInt(LoadError::column));
        return all;
    }

    private static ParsedFrame located(Frame f, FrameElement e) {
        SourceLocation at = e.location();
        long[] slots = new long[e.slots().size()];
        for (int i = 0; i < slots.length; i++) {
            SlotElement s = e.slots().get(i);
            slots[i] = (long) s.line() << 32 | s.column();
        }
        Optional<SourceLocation> isa = e.present(FrameTag.ISA).map(l -> l.at(at.source()));
        return new ParsedFrame(new SourcedFrame(f, at), isa, slots);
    }

    /** A non-empty DESCENDANTS item must name exactly the sub-frames the hierarchy gives the frame. */
    private void checkDescendants(String name, Located declared) {
        Set<String> listed = new LinkedHashSet<>();
        for (Located item : declared.items()) {
            listed.add(item.stripped());
        }
        if (declared.items().isEmpty()) {
            errors.add(LoadError.at(declared.at(sourceOf(name)), "DESCENDANTS of frame '" + name
                    + "' lists its frames as FRAME or ITEM elements, not as text.", name, null));
            return;
        }
        Set<String> derived = new LinkedHashSet<>();
        if (context.contains(name)) {
            context.children(name).forEach(c -> derived.add(c.name()));
        }
        for (ParsedFrame p : parsed) {
            if (p != null && p.sourced().frame().parent().filter(name::equals).isPresent()) {
                derived.add(p.sourced().frame().name());
            }
        }
        // A listed frame that failed to map may well be a kind of this one: its ISA is not known, so it is not held
        // against the list (its own error is reported).
        Set<String> comparable = new HashSet<>(listed);
        comparable.removeIf(n -> failed.contains(n) && !derived.contains(n));
        if (!comparable.equals(new HashSet<>(derived))) {
            errors.add(LoadError.at(declared.at(sourceOf(name)), "Frame '" + name + "' lists DESCENDANTS "
                    + quote(listed) + ", but the frames that are a kind of it are " + quote(derived)
                    + "; descendants are derived from ISA, so list them exactly or leave DESCENDANTS empty.", name, null));
        }
    }

    private String sourceOf(String name) {
        return seen.get(name).source();
    }

    private static String quote(Set<String> names) {
        return names.isEmpty() ? "none" : "'" + String.join("', '", names) + "'";
    }

    /**
     * The nearest ARGUMENT given for {@code slot} on {@code frame} or above it, among the frames read (mapped or not)
     * and then the context: what the knowledge base's declarations give the slot.
     */
    private Optional<String> declaredArgument(String frame, String slot) {
        Set<String> visited = new HashSet<>();
        String current = frame;
        while (current != null && visited.add(current)) {
            Frame f = byName.get(current);
            if (f == null && !unmapped.containsKey(current)) {
                f = above.apply(current).orElse(null);
            }
            if (f != null) {
                Optional<String> own = f.ownSlot(slot).flatMap(Slot::argument);
                if (own.isPresent()) {
                    return own;
                }
                current = f.parent().orElse(null);
                continue;
            }
            FrameElement e = unmapped.get(current);
            if (e == null) {
                return Optional.empty();
            }
            for (SlotElement s : e.slots()) {
                if (s.present(SlotTag.NAME).filter(n -> n.stripped().equals(slot)).isPresent()) {
                    Optional<Located> a = s.present(SlotTag.ARGUMENT);
                    if (a.isPresent()) {
                        return Optional.of(a.get().stripped());
                    }
                }
            }
            current = e.present(FrameTag.ISA).map(Located::stripped).orElse(null);
        }
        return Optional.empty();
    }

    /** The type of {@code slot} as declared on {@code frame} or the nearest frame above it that declares it. */
    private Optional<DataType> declaredType(String frame, String slot) {
        Set<String> visited = new HashSet<>();
        String current = frame;
        while (current != null && visited.add(current)) {
            Frame f = byName.get(current);
            if (f != null) {
                Optional<Slot> own = f.ownSlot(slot);
                if (own.isPresent()) {
                    return Optional.of(own.get().type());
                }
                current = f.parent().orElse(null);
                continue;
            }
            FrameElement e = unmapped.get(current);
            if (e != null) {
                for (SlotElement s : e.slots()) {
                    if (s.present(SlotTag.NAME).filter(n -> n.stripped().equals(slot)).isPresent()) {
                        Optional<DataType> t = s.present(SlotTag.TYPE).flatMap(l -> FrameMapper.dataType(l.stripped()));
                        if (t.isPresent()) {
                            return t;
                        }
                    }
                }
                current = e.present(FrameTag.ISA).map(Located::stripped).orElse(null);
                continue;
            }
            Optional<Frame> known = above.apply(current);
            if (known.isEmpty()) {
                return Optional.empty();
            }
            Optional<Slot> own = known.get().ownSlot(slot);
            if (own.isPresent()) {
                return Optional.of(own.get().type());
            }
            current = known.get().parent().orElse(null);
        }
        return Optional.empty();
    }
}
