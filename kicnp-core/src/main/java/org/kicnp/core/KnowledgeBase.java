package org.kicnp.core;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.function.LongConsumer;
import java.util.function.Supplier;

/**
 * The knowledge base (the paper's knowledge manager): every frame, the indexes derived from them, and the one
 * door through which they change. Thread-safe: reads share a lock, a batch of changes takes it exclusively,
 * is validated as a whole against the state it would produce, made durable by the {@link CommitLog}, applied,
 * and then published to listeners in commit order.
 *
 * <p>"Frame by name" is a hash look-up; "all instances of a class, including its descendants' instances" reads a
 * set kept per class, so it costs O(1) per result and never scans.
 */
public final class KnowledgeBase {
    /** The locks, holds and delivery of batches to listeners. */
    private final Access access = new Access();
    private final NodeIndex nodes = new NodeIndex();
    /**
     * What validation has learnt of the classes (acyclic IS-A chains, inherited slot declarations), kept between
     * batches that change no class and dropped by any batch that does: adding an instance then costs a look-up.
     */
    private final Map<String, ClassInfo> classes = new HashMap<>();
    private final PlainInstanceAdd plain = new PlainInstanceAdd(nodes, classes);
    private final Function<String, Frame> lookup = this::frameOrNull;
    /** Scratch list for validation and indexing, used under the write lock. */
    private final List<String> refs = new ArrayList<>();
    private final CommitLog commitLog;
    private long version;
    /** Adds made by {@link PlainInstanceAdd}, for tests that must know the short cut was taken. */
    private long plainAdds;
    /** Counts the clearings of {@link #classes}: what a prepared {@link InstanceShape} found holds while it stays. */
    private long classEpoch;
    /** Whether plain instances take {@link PlainInstanceAdd}; off only in tests that compare with the general path. */
    private boolean shortCuts = true;

    private KnowledgeBase(CommitLog commitLog) {
        this.commitLog = requireNonNull(commitLog, "commitLog");
    }

    /** An empty knowledge base kept in memory only. */
    public static KnowledgeBase create() {
        return new KnowledgeBase(CommitLog.NONE);
    }

    /** An empty knowledge base that makes every durable change durable through {@code commitLog} first. */
    public static KnowledgeBase create(CommitLog commitLog) {
        return new KnowledgeBase(commitLog);
    }

    // ---- reads ----

    public Optional<Frame> frame(String name) {
        return read(() -> Optional.ofNullable(nodes.get(name)).map(n -> n.frame));
    }

    /** The frame of that name, or {@link UnknownFrameException}. */
    public Frame require(String name) {
        return frame(name).orElseThrow(() -> new UnknownFrameException(name));
    }

    public boolean contains(String name) {
        return read(() -> nodes.containsKey(name));
    }

    public int size() {
        return read(nodes::size);
    }

    /** Every frame, in the order frames were first added (a replace keeps the place). */
    public List<Frame> frames() {
        return read(() -> nodes.values().stream().map(n -> n.frame).toList());
    }

    /** Class frames that have no parent. */
    public List<Frame> roots() {
        return read(() -> nodes.values().stream().filter(n -> n.parent == null && n.frame.isClass())
                .map(n -> n.frame).toList());
    }

    /** The descendants item of Table 1: direct sub-frames, classes and instances alike. */
    public List<Frame> children(String name) {
        return read(() -> {
            Node n = node(name);
            if (n.children == null) {
                return List.of();
            }
            List<Frame> out = new ArrayList<>(n.children.size());
            for (Node c : n.children) {
                out.add(c.frame);
            }
            return out;
        });
    }

    /** Every instance of the class or of any class below it, in the order they were added. */
    public List<Frame> instancesOf(String className) {
        return read(() -> {
            Node n = node(className);
            if (n.instances == null) {
                return List.of();
            }
            List<Frame> out = new ArrayList<>(n.instances.size());
            for (Node i : n.instances) {
                out.add(i.frame);
            }
            return out;
        });
    }

    /** Number of instances of the class or of any class below it. */
    public int countInstancesOf(String className) {
        return read(() -> {
            Node n = node(className);
            return n.instances == null ? 0 : n.instances.size();
        });
    }

    /**
     * Visits every instance of the class or of any class below it without copying, under the read lock.
     * The visitor must not change the knowledge base.
     */
    public void forEachInstanceOf(String className, Consumer<Frame> visitor) {
        read(() -> {
            Node n = node(className);
            if (n.instances != null) {
                for (Node i : n.instances) {
                    visitor.accept(i.frame);
                }
            }
            return null;
        });
    }

    /** Whether {@code frame} is {@code ancestor} or lies below it in the IS-A hierarchy. */
    public boolean isA(String frame, String ancestor) {
        return read(() -> {
            for (Node n = nodes.get(frame); n != null; n = n.parent) {
                if (n.name().equals(ancestor)) {
                    return true;
                }
            }
            return false;
        });
    }

    /** The A-kind-of chain above the frame, nearest first. */
    public List<String> ancestors(String name) {
        return read(() -> {
            List<String> out = new ArrayList<>();
            for (Node n = node(name).parent; n != null; n = n.parent) {
                out.add(n.name());
            }
            return out;
        });
    }

    /** The slot as the frame sees it, looked up on the frame and then up the IS-A chain. */
    public Optional<EffectiveSlot> slot(String frame, String slotName) {
        return read(() -> Inheritance.slot(lookup, node(frame).frame, slotName));
    }

    /** Every slot the frame has, inherited ones included, topmost declarations first. */
    public List<EffectiveSlot> slots(String frame) {
        return read(() -> Inheritance.slots(lookup, node(frame).frame));
    }

    /** The slot's value after inheritance: the nearest value or default. */
    public Optional<Value> value(String frame, String slotName) {
        return read(() -> Inheritance.value(lookup, node(frame).frame, slotName));
    }

    /** Semantic links into the frame: those it declares "from" and those other frames declare "to" it. */
    public List<SemanticLink> linksInto(String name) {
        return links(name, Frame::linksFrom, Frame::linksTo);
    }

    /** Semantic links out of the frame: those it declares "to" and those other frames declare "from" it. */
    public List<SemanticLink> linksOutOf(String name) {
        return links(name, Frame::linksTo, Frame::linksFrom);
    }

    /** The frame's own links of one direction plus the referrers' links of the other direction that name it. */
    private List<SemanticLink> links(String name, java.util.function.Function<Frame, List<SemanticLink>> own,
            java.util.function.Function<Frame, List<SemanticLink>> mirrored) {
        return read(() -> {
            Node n = node(name);
            List<SemanticLink> out = new ArrayList<>(own.apply(n.frame));
            for (Node r : n.referrers()) {
                for (SemanticLink l : mirrored.apply(r.frame)) {
                    if (l.frame().equals(name)) {
                        out.add(new SemanticLink(l.relation(), r.name()));
                    }
                }
            }
            return out;
        });
    }

    /**
     * The frames that mention this one other than as their parent (slot values and arguments, parts, links), in the
     * order they came to mention it: what a change to this frame may affect. Empty for an unknown name.
     */
    public List<String> referrers(String name) {
        return read(() -> {
            Node n = nodes.get(name);
            if (n == null) {
                return List.<String>of();
            }
            List<Node> rs = n.referrers();
            List<String> out = new ArrayList<>(rs.size());
            for (Node r : rs) {
                out.add(r.name());
            }
            return out;
        });
    }

    /** The version of the knowledge base when the frame last changed: the editor's check against lost updates. */
    public long revision(String name) {
        return read(() -> node(name).revision);
    }

    /** How many adds {@link PlainInstanceAdd} made (a test's view of which path an add took). */
    long plainAdds() {
        return read(() -> plainAdds);
    }

    /** Makes every change take the general path, for tests that compare the short cut with it. */
    KnowledgeBase withoutShortCuts() {
        access.write(() -> shortCuts = false);
        return this;
    }

    /** The number of batches committed so far. */
    public long version() {
        return read(() -> version);
    }

    // ---- changes ----

    public ChangeSet add(Frame frame) {
        return apply(List.of(new Change.Add(frame)));
    }

    /**
     * As {@link #add(Frame)}, for a frame that refers to frames the caller has at hand, read from this knowledge base
     * or its events (an inference engine adding the instance a rule derived from the instances it matched): the
     * checks and indexes reach the frames {@code referred} names through them instead of looking their names up.
     * That is only a short cut: a frame of {@code referred} that this knowledge base does not hold now (it was
     * removed, or never added here) is not used, its name is looked up as any other, and the outcome (the change
     * made, or the same {@link BatchRejectedException}) is always that of {@code add(frame)}.
     *
     * @param referred frames {@code frame} may refer to; nulls are skipped
     */
    public ChangeSet add(Frame frame, Frame... referred) {
        requireNonNull(referred, "referred");
        return apply(List.of(new Change.Add(frame)), referred);
    }

    /**
     * Adds the instance of {@code shape} named {@code name} with {@code values} in its slots and returns its frame: the
     * outcome of {@code add(frame, referred)} for that frame (the same change, or the same exception), made with the
     * checks of the shape's class and slot declarations done once while no class changes, and none of the name but
     * that it is the class's name, '-' and digits (an inference engine's adds; any other name takes the general way).
     *
     * <p>The knowledge base keeps neither array: a caller may fill the same ones for its next add.
     *
     * @param referred frames the values may refer to, at hand (see {@link #add(Frame, Frame...)}); nulls are skipped
     * @throws IllegalArgumentException when {@code values} are not as many as the shape's slots
     * @throws InvalidFrameException when the name is not a valid frame name or a value is not a reference
     * @throws BatchRejectedException when the knowledge base refuses the instance, as {@link #add(Frame)} would
     */
    public Frame addInstance(InstanceShape shape, String name, Value[] values, Frame... referred) {
        requireNonNull(shape, "shape");
        requireNonNull(name, "name");
        requireNonNull(referred, "referred");
        ChangeSet added = access.holding() ? access.committedInHold(commitInstance(shape, name, values, referred))
                : access.applied(() -> commitInstance(shape, name, values, referred));
        return added.events().getFirst().frame();
    }

    private ChangeSet commitInstance(InstanceShape shape, String name, Value[] values, Frame[] referred) {
        List<FrameEvent> added = shortCuts ? plain.tryShaped(shape, name, values, referred, version + 1, classEpoch)
                : null;
        if (added == null) {
            return commit(List.of(new Change.Add(shape.frame(name, values))), referred);
        }
        plainAdds++;
        version++;
        return new ChangeSet(version, added);
    }

    public ChangeSet replace(Frame frame) {
        return apply(List.of(new Change.Replace(frame)));
    }

    public ChangeSet put(Frame frame) {
        return apply(List.of(new Change.Put(frame)));
    }

    public ChangeSet remove(String name) {
        return apply(List.of(new Change.Remove(name)));
    }

    /**
     * Applies a batch: all of it, or (on any problem) none of it.
     *
     * @throws BatchRejectedException listing every problem, when the batch breaks a rule of the frame model
     * @throws StaleRevisionException when a replace expected a revision the frame no longer has
     * @throws KnowledgeException when the commit log cannot make the batch durable
     */
    public ChangeSet apply(List<? extends Change> changes) {
        return apply(changes, null);
    }

    /** As {@link #apply(List)}, with frames the batch's frames may refer to at hand ({@link Node#find}), or null. */
    private ChangeSet apply(List<? extends Change> changes, Frame[] near) {
        requireNonNull(changes, "changes");
        return access.applied(() -> commit(changes, near));
    }

    /**
     * A thread's hold on the knowledge base ({@link #hold}): closing it lets other threads read and change it again.
     */
    @FunctionalInterface
    public interface Hold extends AutoCloseable {
        @Override void close();
    }

    /**
     * Holds the knowledge base for the calling thread until the returned hold is closed, for a burst of small changes
     * by one thread (an inference engine firing rule after rule): meanwhile this thread's reads and changes take no
     * lock each, and other threads' wait. Changes are validated, made durable and delivered exactly as without a
     * hold, in commit order, with one difference: listeners hear this thread's changes at once, in this thread, while
     * it still holds the knowledge base (they may read and change it, in this thread, as always; a listener that waits
     * for another thread to read it would wait for the hold to end). Keep holds short.
     *
     * <p>A thread that holds it already, or that is delivering a change to a listener (its changes must wait for every
     * listener to hear that one first), gets a hold that does nothing. A hold closed inside a listener ends when that
     * delivery is over. Closing a hold twice, or from another thread, does nothing.
     */
    public Hold hold() {
        return access.hold();
    }

    /**
     * The problems {@link #apply} would report for this batch now, without applying it or changing anything: empty
     * when it would be applied. For reporting a batch's problems together with others found before it could be
     * applied, such as a loader's errors in the XML of other frames.
     *
     * @throws StaleRevisionException when a replace expects a revision the frame no longer has
     */
    public List<Problem> problems(List<? extends Change> changes) {
        requireNonNull(changes, "changes");
        return read(() -> {
            Batch batch;
            try {
                batch = Batch.stage(changes, nodes);
            } catch (BatchRejectedException e) {
                return e.problems();
            }
            // Its own class memo and scratch list (never the knowledge base's): this runs under the read lock only.
            return List.copyOf(new Validator(batch.staged(), nodes, HashMap.newHashMap(batch.staged().size()),
                    new ArrayList<>()).validate());
        });
    }

    /**
     * Starts a batch of adds given in parts, as a loader reads them, and checked part by part while the caller goes on
     * reading: see {@link StagedBatch}. Its {@link StagedBatch#commit()} is equivalent to {@link #apply} of all the adds.
     */
    public StagedBatch stagedBatch() {
        return new StagedBatch(this);
    }

    /** Runs {@code part} of a staged batch under the read lock, with the version it sees. */
    void readStaged(LongConsumer part) {
        read(() -> {
            part.accept(version);
            return null;
        });
    }

    NodeIndex nodes() {
        return nodes;
    }

    /**
     * Commits a staged batch: if the knowledge base is still at {@code stagedAt}, {@code finish} completes the
     * checks and answers the events, and {@code prepared} (if not null) holds their nodes; otherwise (another batch
     * came in between) the adds are applied as any batch.
     */
    ChangeSet commitStaged(long stagedAt, Supplier<List<FrameEvent>> finish, PreparedNodes prepared,
            boolean classesUnchanged, Supplier<List<Change>> adds) {
        return access.applied(() -> version == stagedAt ? publish(finish.get(), classesUnchanged, prepared, null)
                : commit(adds.get(), null));
    }

    public void addListener(KnowledgeListener listener) {
        access.addListener(requireNonNull(listener, "listener"));
    }

    public void removeListener(KnowledgeListener listener) {
        access.removeListener(listener);
    }

    private ChangeSet commit(List<? extends Change> changes, Frame[] near) {
        if (shortCuts) {
            // Plain instances (stimuli, sensor readings, derived instances) are checked and indexed without staging.
            List<FrameEvent> added = changes.size() == 1 ? plain.tryAdd(changes.getFirst(), near, version + 1)
                    : plain.tryBatch(changes, version + 1);
            if (added != null && !added.isEmpty()) { // an empty batch changes nothing: the general path says so
                plainAdds += added.size();
                version++;
                return new ChangeSet(version, added);
            }
        }
        Batch batch = Batch.stage(changes, nodes);
        boolean classesUnchanged = batch.classesUnchanged();
        Map<String, ClassInfo> known = classesUnchanged ? classes : HashMap.newHashMap(batch.staged().size());
        List<Problem> problems = new Validator(batch.staged(), nodes, known, refs, near).validate();
        if (!problems.isEmpty()) {
            throw new BatchRejectedException(problems);
        }
        return publish(batch.events(nodes), classesUnchanged, null, near);
    }

    /**
     * Makes a validated batch's events durable and applies them; the caller {@linkplain Delivery#queue queues} them
     * for the listeners.
     *
     * @param prepared the batch's nodes, built while it was staged, or null to index the events here
     * @param near frames the batch's frames may refer to, at hand for the indexes ({@link Node#find}), or null
     */
    private ChangeSet publish(List<FrameEvent> events, boolean classesUnchanged, PreparedNodes prepared,
            Frame[] near) {
        if (events.isEmpty()) {
            return new ChangeSet(version, events);
        }
        List<FrameEvent> durable = CommitLog.durableEvents(events);
        if (!durable.isEmpty()) {
            try {
                commitLog.append(version + 1, durable);
            } catch (RuntimeException e) {
                throw new KnowledgeException("The change could not be made durable, so it was not applied: "
                        + e.getMessage(), e);
            }
        }
        version++;
        if (!classesUnchanged) {
            classes.clear();
            classEpoch++;
        }
        if (prepared != null) {
            prepared.attach(nodes, version);
        } else {
            Indexer.apply(nodes, events, version, refs, near);
        }
        return new ChangeSet(version, events);
    }

    private Node node(String name) {
        Node n = nodes.get(name);
        if (n == null) {
            throw new UnknownFrameException(name);
        }
        return n;
    }

    private Frame frameOrNull(String name) {
        Node n = nodes.get(name);
        return n == null ? null : n.frame;
    }

    private <T> T read(Supplier<T> body) {
        return access.read(body);
    }
}
