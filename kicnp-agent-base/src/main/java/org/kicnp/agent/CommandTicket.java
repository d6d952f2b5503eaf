package org.kicnp.agent;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.kicnp.protocol.Message.Command;
import org.kicnp.protocol.Message.Feedback;

/** A command a user agent sent: the feedback so far, and its outcome once it ends or fails. */
public final class CommandTicket {
    private final Command command;
    private final List<Feedback> feedback = new CopyOnWriteArrayList<>();
    private final CompletableFuture<Feedback> outcome = new CompletableFuture<>();

    CommandTicket(Command command) {
        this.command = command;
    }

    public Command command() {
        return command;
    }

    /** Every feedback received so far, in order. */
    public List<Feedback> feedback() {
        return List.copyOf(feedback);
    }

    /**
     * Waits for the command to end and returns its result.
     *
     * @throws ActionFailedException with the reason when it failed
     * @throws AgentTimeoutException when it has not ended within {@code timeout}
     */
    public String result(Duration timeout) {
        Feedback f;
        try {
            f = outcome.get(timeout.toMillis(), TimeUnit.MILLISECONDS);
        } catch (TimeoutException e) {
            throw new AgentTimeoutException("Command '" + command.id() + "' to '" + command.robot()
                    + "' did not end within " + timeout + ".");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AgentException("Interrupted while waiting for command '" + command.id() + "'.", e);
        } catch (ExecutionException e) {
            throw new AgentException("Command '" + command.id() + "' could not complete.", e.getCause());
        }
        return switch (f.stage()) {
            case ENDED -> f.detail();
            case FAILED -> throw new ActionFailedException(f.detail());
            case STARTED, PROGRESS -> throw new IllegalStateException("Not a final stage: " + f.stage());
        };
    }

    void received(Feedback f) {
        feedback.add(f);
        if (f.stage().terminal()) {
            outcome.complete(f);
        }
    }
}
