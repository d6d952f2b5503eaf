package org.kicnp.agent;

import static java.util.Objects.requireNonNull;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.BiConsumer;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.Message.Command;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The robot side of an {@link AgentBase}: runs each command the server sends on a virtual thread of its own through
 * the agent's {@code onCommand}, with an {@link ActionHandle} whose feedback goes to the server, and keeps the
 * commands in flight so that a cancel finds its handle and runs the agent's {@code onCancel} once. A handler that
 * throws ends its command (failed, or "cancel failed") rather than leave it in flight for good; a lost connection cancels
 * every command in flight, since the server fails them and will not hear of them again.
 */
final class CommandRunner {
    /** The agent's own logger category, so that logging set up for the SDK still covers these lines. */
    private static final Logger LOG = LoggerFactory.getLogger(AgentBase.class);

    private final String agent;
    private final BiConsumer<Command, ActionHandle> onCommand;
    private final BiConsumer<ActionHandle, String> onCancel;
    private final ActionHandle.Sender sender;
    /** The commands running, by id, so that a cancel finds its handle. */
    private final Map<String, ActionHandle> running = new ConcurrentHashMap<>();

    /**
     * @param agent     the agent's name, for log lines and the failures it reports
     * @param onCommand the agent's command handler
     * @param onCancel  the agent's cancel handler
     * @param sender    where feedback goes (the agent's current connection)
     */
    CommandRunner(String agent, BiConsumer<Command, ActionHandle> onCommand, BiConsumer<ActionHandle, String> onCancel,
                  ActionHandle.Sender sender) {
        this.agent = requireNonNull(agent, "agent");
        this.onCommand = requireNonNull(onCommand, "onCommand");
        this.onCancel = requireNonNull(onCancel, "onCancel");
        this.sender = requireNonNull(sender, "sender");
    }

    /** How many commands are in flight. */
    int inFlight() {
        return running.size();
    }

    /**
     * Runs a command from the server, on a virtual thread of its own; returns at once. The command is in flight from
     * here on, so that a connection lost the next moment cancels it too (see {@link #connectionLost}).
     */
    void command(Command cmd) {
        ActionHandle handle = new ActionHandle(cmd, f -> report(cmd, f));
        running.put(cmd.id(), handle);
        Thread.ofVirtual().name("command-" + cmd.id()).start(() -> run(cmd, handle));
    }

    /**
     * The connection the commands in flight came on is gone, and the server fails them: each handle is cut off (its
     * later reports are ignored) and, unless it is being cancelled already, cancelled with {@code reason}, so that the
     * agent's {@code onCancel} stops the robot and a program that checks {@link ActionHandle#isCancelRequested()}
     * winds down, as for a cancel from the server.
     */
    void connectionLost(String reason) {
        for (Map.Entry<String, ActionHandle> e : running.entrySet()) {
            ActionHandle h = e.getValue();
            running.remove(e.getKey(), h);
            h.cutOff();
            if (!h.isDone() && h.cancelRequested(reason)) {
                LOG.info("Agent '{}' cancels command '{}': {}.", agent, e.getKey(), reason);
                Thread.ofVirtual().name("cancel-" + e.getKey()).start(() -> runCancel(h, reason));
            }
        }
    }

    /**
     * Asks a running command to stop: its handle records the reason and the agent's {@code onCancel} runs, on a
     * virtual thread of its own, unless the command is not running or is being cancelled already.
     */
    void cancel(Message.Cancel x) {
        ActionHandle h = running.get(x.command());
        if (h == null || h.isDone()) {
            LOG.debug("Agent '{}': cancel of '{}', which is not running.", agent, x.command());
        } else if (!h.cancelRequested(x.reason())) {
            LOG.debug("Agent '{}': '{}' is already being cancelled.", agent, x.command());
        } else {
            Thread.ofVirtual().name("cancel-" + x.command()).start(() -> runCancel(h, x.reason()));
        }
    }

    private void report(Command cmd, Message.Feedback f) {
        if (f.stage().terminal()) {
            running.remove(cmd.id());
        }
        try {
            sender.send(f);
        } catch (NotConnectedException e) {
            // The connection is going: its loss cancels the command, which is how the robot's program hears of it.
            LOG.debug("Agent '{}' could not report on '{}': {}", agent, cmd.id(), e.getMessage());
        }
    }

    private void run(Command cmd, ActionHandle handle) {
        try {
            onCommand.accept(cmd, handle);
        } catch (NotConnectedException e) {
            LOG.info("Agent '{}' lost its connection during command '{}'; the server fails it.", agent, cmd.id());
        } catch (RuntimeException e) {
            LOG.warn("Agent '{}' failed on command '{}'.", agent, cmd.id(), e);
            try {
                if (!handle.isDone()) {
                    handle.failed("Agent '" + agent + "' failed: " + e.getMessage());
                }
            } catch (NotConnectedException lost) {
                LOG.info("Agent '{}' could not report the failure of '{}': {}", agent, cmd.id(), lost.getMessage());
            }
        }
    }

    private void runCancel(ActionHandle handle, String reason) {
        try {
            onCancel.accept(handle, reason);
        } catch (NotConnectedException e) {
            LOG.info("Agent '{}' lost its connection while cancelling '{}'.", agent, handle.command().id());
        } catch (RuntimeException e) {
            LOG.warn("Agent '{}' failed to cancel '{}'.", agent, handle.command().id(), e);
            // As for a command whose onCommand throws: the command ends, rather than stay in flight for good. Not as
            // "cancelled", though: the robot may still be moving, and whoever asked it to stop must know.
            try {
                if (!handle.isDone()) {
                    handle.failed("cancel failed: " + (e.getMessage() == null ? e.toString() : e.getMessage())
                            + " (agent '" + agent + "', asked to stop: " + reason + "); the robot may not have stopped");
                }
            } catch (NotConnectedException lost) {
                LOG.info("Agent '{}' could not report the cancel of '{}': {}", agent, handle.command().id(),
                        lost.getMessage());
            }
        }
    }
}
