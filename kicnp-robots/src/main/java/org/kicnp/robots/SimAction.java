package org.kicnp.robots;

import java.util.Objects;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;

/**
 * A command sent to the simulator and followed until it ends: its id (also the action id in the simulator's
 * events), the observer that gets every {@link ActionUpdate}, and {@link #outcome()}, which completes with the
 * terminal update ({@link ActionUpdate.Ended} or {@link ActionUpdate.Failed}) and never exceptionally.
 */
public final class SimAction {
    private final String id;
    private final SimRequest.Command command;
    private final Consumer<ActionUpdate> observer;
    private final CompletableFuture<ActionUpdate> outcome = new CompletableFuture<>();
    private volatile boolean started;

    SimAction(String id, SimRequest.Command command, Consumer<ActionUpdate> observer) {
        this.id = Objects.requireNonNull(id, "id");
        this.command = Objects.requireNonNull(command, "command");
        this.observer = Objects.requireNonNull(observer, "observer");
    }

    public String id() {
        return id;
    }

    public String robot() {
        return command.robot();
    }

    public String action() {
        return command.action();
    }

    /** Whether the simulator reported {@code action_started} for it. */
    public boolean started() {
        return started;
    }

    /** Completes with the terminal update; a dependent stage runs on the simulator's event thread. */
    public CompletableFuture<ActionUpdate> outcome() {
        return outcome;
    }

    /** Delivers one update, once the action is done no more; called on the event thread only. */
    void deliver(ActionUpdate update) {
        if (outcome.isDone()) {
            return;
        }
        if (update instanceof ActionUpdate.Started) {
            started = true;
        }
        try {
            observer.accept(update);
        } finally {
            if (update.terminal()) {
                outcome.complete(update);
            }
        }
    }

    @Override public String toString() {
        return command.robot() + "." + command.action() + " '" + id + "'";
    }
}
