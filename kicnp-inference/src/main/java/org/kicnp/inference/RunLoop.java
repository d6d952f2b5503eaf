package org.kicnp.inference;

import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Consumer;
import org.kicnp.core.ChangeSet;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * How work reaches the engine and when it runs: change sets and action reports from any thread wait in a queue, and
 * a run drains it and fires activations in agenda order until nothing more fires, failing loudly past the firing
 * limit; on an engine that runs by itself, an arrival schedules the run on its executor. Kept apart from
 * {@link InferenceEngine}, the public front (building, questions, actions), so that one class decides when and on
 * which thread work happens. It shares the engine's lock: every front-end call drains the queue under it first.
 */
final class RunLoop {
    /** Logged under the engine's name: the public class is the one users configure logging for. */
    private static final Logger LOG = LoggerFactory.getLogger(InferenceEngine.class);

    private final ReentrantLock lock;
    private final EngineOptions options;
    private final ForwardChainer forward;
    private final ActionCoordinator actions;
    /** The knowledge base held across firings (see {@link Burst}); given back whenever the run stops firing. */
    private final Burst burst;
    private final Consumer<TraceEvent> tracer;
    private final Optional<Executor> runner;
    private final ConcurrentLinkedQueue<Runnable> inbox = new ConcurrentLinkedQueue<>();
    private final AtomicBoolean scheduled = new AtomicBoolean();
    /** Whether the executor refused the last run it was handed; the warning is logged once per such spell. */
    private volatile boolean refusing;
    /** Whether {@link #run()} is running on the thread that holds {@link #lock}; read under it only. */
    private boolean running;
    /**
     * A change set of the engine's own commit during a run (a firing's instance), held for the run's next drain
     * instead of going through {@link #inbox}: nothing was queued before it, and the run drains it before anything
     * queued after it. Null: none. Read and written under {@link #lock} only.
     */
    private ChangeSet own;
    /**
     * The rules of the run's last {@link #RECENT} firings, a ring (firing {@code i} at {@code i % RECENT}): what the
     * firing limit's error names. A runaway knowledge base is firing its loop by then, and a store per firing costs
     * less than a count per frame kept up to date. Read and written under {@link #lock} only.
     */
    private final Rule[] recent = new Rule[RECENT];
    private static final int RECENT = 4096;

    RunLoop(ReentrantLock lock, EngineOptions options, ForwardChainer forward, ActionCoordinator actions, Burst burst,
            Consumer<TraceEvent> tracer, Optional<Executor> runner) {
        this.lock = lock;
        this.options = options;
        this.forward = forward;
        this.actions = actions;
        this.burst = burst;
        this.tracer = tracer;
        this.runner = runner;
    }

    /** {@link InferenceEngine#runToQuiescence()}: drains the queue and fires until nothing more fires. */
    int run() {
        lock.lock();
        boolean outer = !running;
        running = true;
        try {
            int count = 0;
            // Firings since the run last took in a change from outside it: what the limit counts. A runaway knowledge
            // base feeds itself; a stream of stimuli that each cause a few firings (a self-running engine whose next
            // stimulus lands while it fires, run after run) is not one, however long the run lasts.
            int inARow = 0;
            while (true) {
                inARow = drain() ? 0 : inARow;
                actions.checkTimeouts();
                inARow = drain() ? 0 : inARow;
                Activation next = forward.next();
                if (next == null) {
                    burst.release();
                    actions.releaseSynchronized();
                    if (own == null && inbox.isEmpty()) {
                        return count;
                    }
                    continue;
                }
                if (!forward.mayFire(next)) {
                    continue; // blocked when its turn came: not a firing, so not counted against the limit
                }
                recent[count % RECENT] = next.rule();
                count++;
                inARow++;
                if (inARow > options.maxFirings()) {
                    forward.clearAgenda();
                    List<String> top = mostFiring(count, Math.min(inARow, RECENT));
                    throw stopped(options.maxFirings(), new InferenceLimitException(options.maxFirings(), top));
                }
                // A runaway fed by changes from outside often enough never fires maxFirings in a row; the chain of
                // instances it derives, each from the one before, grows all the same.
                int depth = Derivation.depthOver(next.refs());
                if (depth > options.maxDerivationDepth()) {
                    forward.clearAgenda();
                    List<String> top = mostFiring(count, Math.min(count, RECENT));
                    throw stopped(options.maxDerivationDepth(), InferenceLimitException.deeperThan(
                            options.maxDerivationDepth(), next.rule().frame(), top));
                }
                burst.beforeFiring();
                forward.fire(next, depth);
                burst.afterFiring();
            }
        } finally {
            burst.release();
            if (outer) {
                // Every run writes the ring from its first slot on, and this empties it, so what the runs wrote is the
                // slots before the first empty one: let go, so that a rule removed since is not kept between runs.
                for (int i = 0; i < RECENT && recent[i] != null; i++) {
                    recent[i] = null;
                }
                running = false;
                if (own != null) { // a run that ended by an exception: the change set waits in the queue as any other
                    ChangeSet cs = own;
                    own = null;
                    submit(() -> forward.process(cs));
                }
            }
            lock.unlock();
        }
    }

    /** Traces a limit's stop of the run and returns the exception the run ends with. */
    private InferenceLimitException stopped(int limit, InferenceLimitException e) {
        tracer.accept(new TraceEvent.LimitReached(limit, e.topFrames(), e.getMessage()));
        return e;
    }

    /**
     * The frames that fired most among the last {@code n} of the run's {@code count} firings, most first (at most
     * three; ties in the order of each frame's first firing there).
     */
    private List<String> mostFiring(int count, int n) {
        Map<String, int[]> perFrame = new LinkedHashMap<>();
        for (int i = count - n; i < count; i++) {
            perFrame.computeIfAbsent(recent[i % RECENT].frame(), f -> new int[1])[0]++;
        }
        return perFrame.entrySet().stream()
                .sorted(Comparator.comparingInt((Map.Entry<String, int[]> e) -> e.getValue()[0]).reversed())
                .limit(3).map(Map.Entry::getKey).toList();
    }

    /** Forgets what was queued before the engine attached: {@link ForwardChainer#start} sees it all. */
    void clearInbox() {
        inbox.clear();
    }

    /** A committed batch of the knowledge base, from any thread (the engine's listener). */
    void changed(ChangeSet cs) {
        if (lock.isHeldByCurrentThread() && running && own == null && inbox.isEmpty()) {
            own = cs; // the run's own commit: its next drain takes it first, with no queue between
            return;
        }
        submit(() -> forward.process(cs));
    }

    /**
     * Queues work for the engine thread and, on an engine that runs by itself, schedules a run. Work from outside a
     * run (another thread, or the engine thread between runs) is marked so, for the firing limit ({@link #run}).
     */
    void submit(Runnable work) {
        inbox.add(lock.isHeldByCurrentThread() && running ? work : new FromOutside(work));
        runner.ifPresent(ex -> {
            if (scheduled.compareAndSet(false, true)) {
                schedule(ex);
            }
        });
    }

    /**
     * Hands a run to the engine's executor. One that refuses it (shut down, or a bounded pool that is full) leaves the
     * work queued and the run unscheduled, so the next arrival or {@link InferenceEngine#tick()} schedules it again; the
     * caller, often a robot's feedback or a commit of the knowledge base on another thread, is not failed for it.
     */
    private void schedule(Executor ex) {
        try {
            ex.execute(() -> {
                scheduled.set(false);
                try {
                    run();
                } catch (RuntimeException e) {
                    LOG.error("Inference run failed: {}", e.getMessage(), e);
                }
            });
            if (refusing) { // read first: no write to the shared field for every run handed over
                refusing = false;
            }
        } catch (RejectedExecutionException e) {
            scheduled.set(false);
            if (!refusing) { // once until it takes a run again: an executor shut down refuses every arrival after
                refusing = true;
                LOG.warn("The engine's executor refused a run ({}); what is queued waits for the next one.",
                        e.getMessage());
            } else {
                LOG.debug("The engine's executor refused a run again ({}).", e.getMessage());
            }
        }
    }

    /**
     * Runs what waits, the run's own commit first; called under the lock, before anything reads the engine. Returns
     * whether any of it came from outside the run.
     */
    boolean drain() {
        boolean fromOutside = false;
        while (true) {
            if (own != null) { // nothing is queued before it (see changed)
                ChangeSet cs = own;
                own = null;
                forward.process(cs);
                continue;
            }
            Runnable r = inbox.poll();
            if (r == null) {
                return fromOutside;
            }
            fromOutside |= r instanceof FromOutside;
            r.run();
        }
    }

    /** Work queued from outside a run ({@link #submit}). */
    private record FromOutside(Runnable work) implements Runnable {
        @Override public void run() {
            work.run();
        }
    }
}
