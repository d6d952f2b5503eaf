package org.kicnp.gateway;

import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import org.kicnp.core.KnowledgeException;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.ErrorCode;
import org.kicnp.protocol.FeedbackStage;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.Message.Command;
import org.kicnp.protocol.Message.ErrorReply;
import org.kicnp.protocol.Message.Feedback;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Commands in flight: sends them to robots' agents, routes their feedback to the {@link FeedbackListener} (and to
 * the user agent that issued one), mirrors it into the knowledge base, and fails every command of a robot whose
 * connection closes. The platform's {@link ActionSink}. Thread-safe.
 */
final class Commands implements ActionSink {
    private static final Logger LOG = LoggerFactory.getLogger(Commands.class);
    /** The most commands one robot connection may have in flight: bounds the table against a robot that never answers. */
    static final int MAX_IN_FLIGHT_PER_ROBOT = 1024;

    /** A command sent to {@code robot}'s connection, issued by a user agent or (empty) by the platform. */
    private record InFlight(Command command, Session robot, Optional<Session> issuer) {
    }

    private final Map<String, InFlight> inFlight = new ConcurrentHashMap<>();
    private final AgentRegistry registry;
    private final Outbound out;
    private final RuntimeFrames runtime;
    private final FeedbackListener listener;
    /** Set when the gateway shuts down: the robots' connections then close because of that, not of the robots. */
    private volatile boolean closing;

    Commands(AgentRegistry registry, Outbound out, RuntimeFrames runtime, FeedbackListener listener) {
        this.registry = registry;
        this.out = out;
        this.runtime = runtime;
        this.listener = listener;
    }

    @Override public void send(Command command) {
        Optional<ErrorReply> refused = dispatch(command, Optional.empty());
        refused.ifPresent(e -> {
            if (e.code() == ErrorCode.REJECTED) {
                throw new IllegalArgumentException(e.message());
            }
            notify(command, new Feedback(command.id(), command.robot(), FeedbackStage.FAILED, Optional.empty(),
                    e.message()));
        });
    }

    /** A command from a user agent: the answer for the user, an ack or why it could not be sent. */
    Message fromAgent(Session issuer, Command command) {
        // As for cancel: robots act on commands and peers exchange knowledge; neither sends a robot orders.
        if (issuer.kind() == AgentKind.ROBOT || issuer.kind() == AgentKind.PEER) {
            return ErrorReply.to(command.id(), ErrorCode.FORBIDDEN, "Only user and service agents may send "
                    + "commands; " + issuer + " is a " + issuer.kind().name().toLowerCase(java.util.Locale.ROOT)
                    + " agent, so command '" + command.id() + "' to '" + command.robot() + "' was not sent.");
        }
        return dispatch(command, Optional.of(issuer)).<Message>map(e -> e).orElseGet(() -> new Message.Ack(command.id()));
    }

    private Optional<ErrorReply> dispatch(Command c, Optional<Session> issuer) {
        Optional<Session> robot = registry.find(c.robot());
        if (robot.isEmpty()) {
            return Optional.of(ErrorReply.to(c.id(), ErrorCode.UNKNOWN_AGENT,
                    "Agent '" + c.robot() + "' is not connected, so command '" + c.id() + "' cannot be sent."));
        }
        Optional<String> clash = runtime.feedbackClash(c);
        if (clash.isPresent()) {
            return Optional.of(ErrorReply.to(c.id(), ErrorCode.REJECTED, "Command '" + c.id() + "' to '" + c.robot()
                    + "' was not sent: " + clash.get()));
        }
        InFlight entry = new InFlight(c, robot.get(), issuer);
        if (robot.get().commandsInFlight.incrementAndGet() > MAX_IN_FLIGHT_PER_ROBOT) {
            robot.get().commandsInFlight.decrementAndGet();
            return Optional.of(ErrorReply.to(c.id(), ErrorCode.REJECTED, "Agent '" + c.robot() + "' already has "
                    + MAX_IN_FLIGHT_PER_ROBOT + " commands in flight; command '" + c.id() + "' was not sent."));
        }
        if (inFlight.putIfAbsent(key(c.robot(), c.id()), entry) != null) {
            robot.get().commandsInFlight.decrementAndGet();
            return Optional.of(ErrorReply.to(c.id(), ErrorCode.REJECTED,
                    "A command '" + c.id() + "' to '" + c.robot() + "' is already in flight."));
        }
        if (!out.send(robot.get(), c)) {
            remove(key(c.robot(), c.id()), entry);
            return Optional.of(ErrorReply.to(c.id(), ErrorCode.AGENT_DISCONNECTED,
                    "Command '" + c.id() + "' could not be sent: agent '" + c.robot() + "' is not reading."));
        }
        return Optional.empty();
    }

    @Override public boolean cancel(String robot, String commandId, String reason) {
        InFlight entry = inFlight.get(key(robot, commandId));
        return entry != null && out.send(entry.robot(), new Message.Cancel("", robot, commandId, reason));
    }

    /**
     * A cancel from an agent: user and service agents may cancel any command in flight (an operator stops a robot
     * whoever started it); a robot stops its own commands by failing them. Answers {@code ack} once the cancel is on
     * its way to the robot, whose answer is the command's last feedback.
     */
    Message cancelFromAgent(Session from, Message.Cancel c) {
        if (from.kind() == AgentKind.ROBOT || from.kind() == AgentKind.PEER) {
            return ErrorReply.to(c.id(), ErrorCode.FORBIDDEN, "Only user and service agents may cancel commands; "
                    + from + " is a " + from.kind().name().toLowerCase(java.util.Locale.ROOT) + " agent.");
        }
        String reason = (c.reason().isBlank() ? "no reason given" : c.reason().strip()) + " (asked by '" + from.agent()
                + "')";
        if (!cancel(c.robot(), c.command(), reason)) {
            return ErrorReply.to(c.id(), ErrorCode.REJECTED, "No command '" + c.command() + "' to '" + c.robot()
                    + "' is in flight.");
        }
        return new Message.Ack(c.id());
    }

    /** Feedback from a robot's agent. Feedback for no command in flight is logged and dropped. */
    void feedback(Session robot, Feedback received) {
        Feedback f = received.from(robot.agent());
        String key = key(robot.agent(), f.id());
        InFlight entry = inFlight.get(key);
        if (entry != null && f.stage().terminal() && !remove(key, entry)) {
            entry = null; // failed by a disconnect at the same moment
        }
        if (entry == null) {
            LOG.debug("Dropping {} feedback from '{}' for command '{}', which is not in flight.", f.stage(),
                    robot.agent(), f.id());
            return;
        }
        try {
            runtime.feedback(entry.command(), f);
        } catch (KnowledgeException | IllegalArgumentException e) { // the latter: another action's feedback took the frame
            LOG.warn("Could not record feedback of command '{}' from '{}': {}", f.id(), robot.agent(), e.getMessage());
        }
        deliver(entry, f);
    }

    /**
     * The gateway is shutting down: from now on a robot's connection that closes fails its commands as the gateway's
     * doing, and an agent that issued one is not sent that failure, its own connection closing too (its SDK reports the
     * lost connection, whichever connection the shutdown closes first).
     */
    void closing() {
        closing = true;
    }

    /** Fails every command in flight on a robot connection that closed. */
    void connectionClosed(Session robot) {
        inFlight.forEach((key, entry) -> {
            if (entry.robot() == robot && remove(key, entry)) {
                Feedback failed = new Feedback(entry.command().id(), robot.agent(), FeedbackStage.FAILED,
                        Optional.empty(), closing ? "the gateway shut down" : "agent '" + robot.agent() + "' disconnected");
                try {
                    runtime.feedback(entry.command(), failed);
                } catch (KnowledgeException | IllegalArgumentException e) {
                    LOG.warn("Could not record the failure of command '{}': {}", entry.command().id(), e.getMessage());
                }
                if (!closing || entry.issuer().isEmpty()) {
                    deliver(entry, failed);
                }
            }
        });
    }

    private boolean remove(String key, InFlight entry) {
        if (inFlight.remove(key, entry)) {
            entry.robot().commandsInFlight.decrementAndGet();
            return true;
        }
        return false;
    }

    int inFlightCount() {
        return inFlight.size();
    }

    private void deliver(InFlight entry, Feedback f) {
        if (entry.issuer().isPresent()) {
            out.send(entry.issuer().get(), f);
        } else {
            notify(entry.command(), f);
        }
    }

    private void notify(Command c, Feedback f) {
        try {
            switch (f.stage()) {
                case STARTED -> listener.started(c);
                case PROGRESS -> listener.progress(c, f.progress().orElse(Double.NaN), f.detail());
                case ENDED -> listener.ended(c, f.detail());
                case FAILED -> listener.failed(c, f.detail());
            }
        } catch (RuntimeException e) {
            LOG.error("The feedback listener failed on {} of command '{}'.", f.stage(), c.id(), e);
        }
    }

    private static String key(String robot, String id) {
        return robot + '\u0000' + id;
    }
}
