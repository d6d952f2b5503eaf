package org.kicnp.robots;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

/**
 * The event thread of a {@link SimWorld}: each event from the simulator goes, in stream order, first to the
 * {@link SimAction} it concerns as an {@link ActionUpdate}, then to every listener. An observer or listener that throws
 * is logged and skipped, so one bad listener neither stops the others nor the stream.
 *
 * <p>Kept apart from the world's reader, which must never run listener code (a slow listener would stall the acks
 * that callers wait for), and from the requests, which only need to post work here.
 */
final class SimEventThread {
    /** The world's logger, so that logging set up for the simulator still covers these lines. */
    private static final Logger LOG = LoggerFactory.getLogger(SimWorld.class);

    private final ExecutorService thread =
            Executors.newSingleThreadExecutor(Thread.ofPlatform().daemon().name("sim-events").factory());
    private final List<Consumer<SimEvent>> listeners = new CopyOnWriteArrayList<>();
    /** The world's actions in flight, by request id (the world adds and removes them). */
    private final Map<String, SimAction> actions;

    SimEventThread(Map<String, SimAction> actions) {
        this.actions = actions;
    }

    /** Adds a listener for every event; closing the result removes it. */
    AutoCloseable addListener(Consumer<SimEvent> listener) {
        listeners.add(listener);
        return () -> listeners.remove(listener);
    }

    /** Runs a task on the event thread, or here once that thread is gone (after death). */
    void post(Runnable task) {
        try {
            thread.execute(task);
        } catch (RejectedExecutionException e) {
            task.run();
        }
    }

    /** On the event thread: the action's update first, then the listeners. */
    void dispatch(SimEvent event) {
        switch (event) {
            case SimEvent.ActionStarted s -> toAction(s.id(), new ActionUpdate.Started(s.t(), s.args()));
            case SimEvent.ActionProgress p -> toAction(p.id(), new ActionUpdate.Progress(p.t(), p.fraction(), p.body()));
            case SimEvent.ActionEnded e -> toAction(e.id(), new ActionUpdate.Ended(e.t(), e.result()));
            case SimEvent.ActionFailed f -> toAction(f.id(), new ActionUpdate.Failed(f.t(), f.reason()));
            case SimEvent.Error err -> err.id().ifPresent(id -> toAction(id, new ActionUpdate.Failed(err.t(), err.message())));
            case SimEvent.Hello h -> { }
            case SimEvent.Ack a -> { }
            case SimEvent.Face f -> { }
            case SimEvent.Bumper b -> { }
            case SimEvent.Arrival a -> { }
            case SimEvent.Fall f -> { }
            case SimEvent.Utterance u -> { }
            case SimEvent.State s -> { }
            case SimEvent.Exited x -> { }
        }
        for (Consumer<SimEvent> l : listeners) {
            try {
                l.accept(event);
            } catch (RuntimeException e) {
                LOG.warn("A simulator listener failed on {}: {}", event.getClass().getSimpleName(), e.toString(), e);
            }
        }
    }

    private void toAction(String id, ActionUpdate update) {
        SimAction a = actions.get(id);
        if (a != null) {
            deliverSafely(a, update);
        }
    }

    /** Gives an action an update; an observer that throws is logged. */
    static void deliverSafely(SimAction action, ActionUpdate update) {
        try {
            action.deliver(update);
        } catch (RuntimeException e) {
            LOG.warn("The observer of {} failed: {}", action, e.toString(), e);
        }
    }

    /** Lets the tasks posted so far run, then ends the thread; later posts run on the poster's thread. */
    void shutdown() {
        thread.shutdown();
    }

    /** Waits for the thread to end after {@link #shutdown}. */
    boolean awaitTermination(long timeout, TimeUnit unit) throws InterruptedException {
        return thread.awaitTermination(timeout, unit);
    }
}
