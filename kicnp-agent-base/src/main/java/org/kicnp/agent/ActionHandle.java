package org.kicnp.agent;

import static java.util.Objects.requireNonNull;

import java.util.Optional;
import java.util.concurrent.atomic.AtomicBoolean;
import org.kicnp.protocol.FeedbackStage;
import org.kicnp.protocol.Message.Command;
import org.kicnp.protocol.Message.Feedback;

/**
 * How a robot reports on one command: {@link #started()}, any number of {@link #progress}, then exactly one of
 * {@link #ended}, {@link #failed} or {@link #cancelled}. May be used from any thread, also after {@code onCommand}
 * returned. A cancel asked for while it runs shows in {@link #isCancelRequested()}. When the agent's connection to the
 * gateway is lost, the command is cancelled (reason "the connection to the gateway was lost") and every later report
 * on it is ignored: the gateway has failed it already.
 */
public final class ActionHandle {
    /** Where feedback goes: the agent's current connection. */
    @FunctionalInterface
    interface Sender {
        void send(Feedback feedback);
    }

    private final Command command;
    private final Sender sender;
    private final AtomicBoolean done = new AtomicBoolean();
    /** Why a cancel was asked for, or null; once the command is reported cancelled, later reports are ignored. */
    private volatile String cancelReason;
    private volatile boolean reportedCancelled;
    /** Whether the connection the command came on is gone; its reports then go nowhere, and are dropped. */
    private volatile boolean cutOff;

    ActionHandle(Command command, Sender sender) {
        this.command = requireNonNull(command, "command");
        this.sender = sender;
    }

    public Command command() {
        return command;
    }

    public void started() {
        report(FeedbackStage.STARTED, Optional.empty(), "");
    }

    /**
     * Reports progress: the fraction done (0.0 to 1.0) and a note.
     *
     * @throws IllegalArgumentException when {@code fraction} is not from 0.0 to 1.0 (NaN included); nothing is sent
     */
    public void progress(double fraction, String note) {
        report(FeedbackStage.PROGRESS, Optional.of(fraction), note);
    }

    /** The command ended; {@code result} tells what came of it. */
    public void ended(String result) {
        finish(FeedbackStage.ENDED, result);
    }

    /** The command failed; {@code reason} says why, for people. */
    public void failed(String reason) {
        finish(FeedbackStage.FAILED, reason);
    }

    /**
     * Reports the command stopped because it was cancelled: {@code failed} with "cancelled: " and the reason. The
     * robot's work on the command may still be winding down: its later reports (progress, ended, failed) are ignored.
     */
    public void cancelled(String reason) {
        if (done.compareAndSet(false, true) && !cutOff) {
            reportedCancelled = true;
            sender.send(new Feedback(command.id(), command.robot(), FeedbackStage.FAILED, Optional.empty(),
                    "cancelled: " + requireNonNull(reason, "reason")));
        }
    }

    /** Whether a cancel was asked for: a long command checks this between its steps and stops early. */
    public boolean isCancelRequested() {
        return cancelReason != null;
    }

    /** Why a cancel was asked for, once one was. */
    public Optional<String> cancelReason() {
        return Optional.ofNullable(cancelReason);
    }

    /** Records the first cancel asked for; false for a later one, which {@code onCancel} does not hear again. */
    synchronized boolean cancelRequested(String reason) {
        if (cancelReason != null) {
            return false;
        }
        cancelReason = reason;
        return true;
    }

    /** Marks the command as cut off from the server by a lost connection: later reports are ignored. */
    void cutOff() {
        cutOff = true;
    }

    /** Whether {@link #ended} or {@link #failed} was called. */
    public boolean isDone() {
        return done.get();
    }

    private void finish(FeedbackStage stage, String detail) {
        if (reportedCancelled) {
            return; // the command was reported cancelled; the robot's work on it has just wound down
        }
        if (!done.compareAndSet(false, true)) {
            if (cancelReason != null) {
                return; // a cancel was asked for: the robot's program and its onCancel may both report the end
            }
            throw new IllegalStateException("Command '" + command.id() + "' was already reported as done.");
        }
        if (cutOff) {
            return;
        }
        sender.send(new Feedback(command.id(), command.robot(), stage, Optional.empty(), requireNonNull(detail, "detail")));
    }

    private void report(FeedbackStage stage, Optional<Double> fraction, String note) {
        if (reportedCancelled) {
            return;
        }
        if (done.get()) {
            if (cancelReason != null) {
                return; // onCancel reported the end; the robot's program is still winding down
            }
            throw new IllegalStateException("Command '" + command.id() + "' is done; no more " 
                    + stage.name().toLowerCase(java.util.Locale.ROOT) + " reports.");
        }
        if (cutOff) {
            return;
        }
        sender.send(new Feedback(command.id(), command.robot(), stage, fraction, requireNonNull(note, "note")));
    }
}
