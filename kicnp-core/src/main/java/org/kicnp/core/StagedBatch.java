package org.kicnp.core;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Frames added to a knowledge base in parts and committed at once, all or nothing: the loader gives each part as soon
 * as it is read, and the part is checked then, under the read lock, while the loader goes on reading on another
 * thread. {@link #commit()} finishes the checks and applies every frame in one batch; it is equivalent to
 * {@link KnowledgeBase#apply} of all the adds in the order given (same frames, order, events and problems).
 *
 * <p>A frame is checked against the frames given so far and the knowledge base; one with no problem whose IS-A chain
 * ends at a root is settled, since adding frames cannot give it a problem (except sub-frames of an instance, which
 * the commit looks for). The others are checked again at the commit. If the knowledge base changed in between, the
 * commit checks everything again, as a plain batch. Used by one thread at a time; nothing changes before
 * {@link #commit()}, so an abandoned batch needs no clean-up.
 */
public final class StagedBatch {
    private final KnowledgeBase kb;
    /** Every frame given, duplicates included, for a commit that has to start over. */
    private final List<Frame> given = new ArrayList<>();
    private final Map<String, Frame> staged = new LinkedHashMap<>();
    private final List<Frame> unsettled = new ArrayList<>();
    private final List<Problem> duplicates = new ArrayList<>(0);
    private Validator validator;
    /** The nodes, built as frames come; null once a frame came before its parent or a frame it refers to. */
    private PreparedNodes prepared;
    private long stagedAt = -1;
    private boolean stale;
    private boolean classesUnchanged = true;
    private boolean committed;

    StagedBatch(KnowledgeBase kb) {
        this.kb = kb;
    }

    /** Stages and checks more frames, after those given before. */
    public void add(List<Frame> frames) {
        if (committed) {
            throw new IllegalStateException("This staged batch has been committed; start a new one.");
        }
        kb.readStaged(version -> {
            if (validator == null) {
                stagedAt = version;
                // Its own class memo (never the knowledge base's): this runs under the read lock only.
                validator = new Validator(staged, kb.nodes(), new HashMap<>(), new ArrayList<>());
                prepared = new PreparedNodes(kb.nodes());
            } else if (version != stagedAt) {
                stale = true;
                prepared = null;
            }
            for (Frame f : frames) {
                stage(f);
            }
        });
    }

    private void stage(Frame f) {
        given.add(f);
        String name = f.name();
        if (staged.containsKey(name) || kb.nodes().containsKey(name)) {
            duplicates.add(Problem.of(name, "A frame named '" + name + "' already exists."));
            return;
        }
        staged.put(name, f);
        if (f.isClass()) {
            classesUnchanged = false;
        }
        if (stale || !duplicates.isEmpty()) {
            return;
        }
        if (!validator.settles(f)) {
            unsettled.add(f);
        }
        if (prepared != null && !prepared.add(f)) {
            prepared = null;
        }
    }

    /**
     * Applies every frame given, or none.
     *
     * @throws BatchRejectedException listing every problem, as {@link KnowledgeBase#apply} would
     */
    public ChangeSet commit() {
        if (committed) {
            throw new IllegalStateException("This staged batch has been committed already.");
        }
        committed = true;
        return kb.commitStaged(stale || validator == null ? -1 : stagedAt, this::finish, prepared, classesUnchanged, () -> {
            List<Change> adds = new ArrayList<>(given.size());
            for (Frame f : given) {
                adds.add(new Change.Add(f));
            }
            return adds;
        });
    }

    /** Under the write lock, on a knowledge base unchanged since the first part: the last checks, then the events. */
    private List<FrameEvent> finish() {
        if (!duplicates.isEmpty()) {
            throw new BatchRejectedException(duplicates);
        }
        List<Problem> problems = validator.finish(unsettled);
        if (!problems.isEmpty()) {
            throw new BatchRejectedException(problems);
        }
        List<FrameEvent> events = new ArrayList<>(staged.size());
        for (Frame f : staged.values()) {
            events.add(new FrameEvent.Added(f));
        }
        return events;
    }
}
