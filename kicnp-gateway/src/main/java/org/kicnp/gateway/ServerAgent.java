package org.kicnp.gateway;

import io.netty.buffer.ByteBuf;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import org.kicnp.core.BatchRejectedException;
import org.kicnp.core.Change;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.KnowledgeException;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.ErrorCode;
import org.kicnp.protocol.FrameText;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.Message.ErrorReply;
import org.kicnp.protocol.RelayRoute;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The paper's server agent, "a message-switching hub": authenticates agents, registers them with their
 * capabilities and presence, relays messages to an agent or to every agent of a kind, records sensor signals, and
 * cleans up after an agent that goes away. The per-connection {@link GatewayHandler} calls it.
 */
final class ServerAgent {
    private static final Logger LOG = LoggerFactory.getLogger(ServerAgent.class);

    private final String serverName;
    private final AgentDirectory directory;
    private final AgentRegistry registry;
    private final KnowledgeBase kb;
    private final RuntimeFrames runtime;
    private final Outbound out;
    private final Commands commands;
    private final KnowledgeAccess knowledge;

    ServerAgent(String serverName, AgentDirectory directory, AgentRegistry registry, KnowledgeBase kb,
                RuntimeFrames runtime, Outbound out, Commands commands, KnowledgeAccess knowledge) {
        this.serverName = serverName;
        this.directory = directory;
        this.registry = registry;
        this.kb = kb;
        this.runtime = runtime;
        this.out = out;
        this.commands = commands;
        this.knowledge = knowledge;
    }

    /** Wires the server agent and its parts over a knowledge base. */
    static ServerAgent create(GatewayConfig config, AgentDirectory directory, KnowledgeBase kb,
                              FeedbackListener feedback, Retraction retraction, Reasoning reasoning,
                              GatewayMetrics metrics) {
        AgentRegistry registry = new AgentRegistry();
        Outbound out = new Outbound(metrics, config.maxShedBeforeDrop());
        RuntimeFrames runtime = new RuntimeFrames(kb, retraction, config.clock());
        KnowledgeAccess knowledge = new KnowledgeAccess(kb, out, retraction, reasoning, config.clock());
        Commands commands = new Commands(registry, out, runtime, feedback);
        return new ServerAgent(config.serverName(), directory, registry, kb, runtime, out, commands, knowledge);
    }

    Commands commands() {
        return commands;
    }

    KnowledgeAccess knowledge() {
        return knowledge;
    }

    RuntimeFrames runtime() {
        return runtime;
    }

    Outbound out() {
        return out;
    }

    /** Checks a hello; on refusal answers and closes, on success marks the session authenticated. */
    void authenticate(Session s, Message.Hello hello) {
        Optional<String> refusal = directory.refusal(hello);
        if (refusal.isPresent()) {
            LOG.info("Refused {} as '{}': {}", s, hello.agent(), refusal.get());
            s.closing();
            s.channel().writeAndFlush(new Message.AuthResult(hello.id(), false, serverName, refusal))
                    .addListener(io.netty.channel.ChannelFutureListener.CLOSE);
            return;
        }
        s.authenticated(hello.agent(), hello.kind());
        LOG.info("Agent '{}' authenticated as {} from {}.", hello.agent(), hello.kind(), s.channel().remoteAddress());
        out.send(s, new Message.AuthResult(hello.id(), true, serverName, Optional.empty()));
    }

    /**
     * Stores the capability frames (all or none), answers, then registers the agent and its presence. The answer is
     * queued before the agent can be found: whatever is sent to it once it is found — a command the engine issues
     * the moment its presence is asserted, a relay from an agent that saw it arrive — comes after the answer its
     * agent waits for. Returns the refusal, if it is refused.
     */
    Optional<Message> register(Session s, Message.Register r) {
        List<Change> changes = new ArrayList<>();
        List<String> names = new ArrayList<>();
        try {
            List<String> forbidden = new ArrayList<>();
            // One set, not text by text: a frame inherits a list's item type from a capability class sent beside it.
            for (Frame f : FrameText.parse(r.capabilities(), i -> "register from " + s + " #" + (i + 1), kb)) {
                kb.frame(f.name()).flatMap(old -> Capabilities.whyNotReplaceable(old, kb.slots(old.name()), f))
                        .ifPresent(forbidden::add);
                changes.add(new Change.Put(f));
                names.add(f.name());
            }
            if (!forbidden.isEmpty()) {
                return Optional.of(ErrorReply.to(r.id(), ErrorCode.FORBIDDEN, "The capabilities of " + s
                        + " were refused: " + String.join(" ", forbidden)));
            }
            if (!changes.isEmpty()) {
                kb.apply(changes);
            }
        } catch (BatchRejectedException e) {
            StringBuilder sb = new StringBuilder("The capabilities of " + s + " were refused:");
            e.problems().forEach(p -> sb.append(' ').append(p));
            return Optional.of(ErrorReply.to(r.id(), ErrorCode.REJECTED, sb.toString()));
        } catch (KnowledgeException | IllegalArgumentException e) {
            return Optional.of(ErrorReply.to(r.id(), ErrorCode.REJECTED, e.getMessage()));
        }
        s.registered(names);
        out.send(s, new Message.Ack(r.id()));
        registry.register(s).ifPresent(old -> {
            LOG.info("Agent {} registered again from a new connection; closing the old one.", s);
            out.closeWith(old, ErrorReply.of(ErrorCode.SUPERSEDED, "Agent " + s + " registered again from a new connection."));
        });
        try {
            runtime.present(s.agent(), s.kind(), names);
        } catch (KnowledgeException e) {
            LOG.warn("Could not record the presence of {}: {}", s, e.getMessage());
        }
        LOG.info("Agent {} registered with {} capability frame(s).", s, names.size());
        return Optional.empty();
    }

    /**
     * Relays to one agent or to every agent of a kind (not back to the sender). Answers {@code ack}, or nothing when
     * the relay's id is empty (fire and forget); a refusal — no such agent, or no other agent of the kind, so that
     * nobody would receive it — is answered either way.
     */
    Optional<Message> relay(Session from, Message.Relay r) {
        Message.Relay stamped = r.from(from.agent());
        if (stamped.toAgent().isPresent()) {
            String to = stamped.toAgent().get();
            Optional<Session> target = registry.find(to);
            if (target.isEmpty()) {
                return Optional.of(unknownAgent(r.id(), to));
            }
            out.send(target.get(), stamped);
        } else {
            List<Session> targets = othersOfKind(from, stamped.toKind().orElseThrow());
            if (targets.isEmpty()) {
                return Optional.of(noneOfKind(r.id(), stamped.toKind().get()));
            }
            targets.forEach(target -> out.send(target, stamped));
        }
        return acked(r.id());
    }

    /**
     * Relays a plain relay's frame as it is, to one agent or to every agent of a kind (not back to the sender): the
     * {@code length} bytes of {@code source} from {@code index}, length prefix included, which the caller keeps (see
     * {@link Outbound#forward}); the caller has checked that the frame names {@code from} as its sender.
     */
    Optional<Message> relayFrame(Session from, RelayRoute route, ByteBuf source, int index, int length) {
        if (route.toAgent().isPresent()) {
            String to = route.toAgent().get();
            Session target = registry.sessionOf(to);
            if (target == null) {
                return Optional.of(unknownAgent(route.id(), to));
            }
            out.forward(target, source, index, length);
        } else {
            List<Session> targets = othersOfKind(from, route.toKind().orElseThrow());
            if (targets.isEmpty()) {
                return Optional.of(noneOfKind(route.id(), route.toKind().get()));
            }
            for (Session target : targets) {
                out.forward(target, source, index, length);
            }
        }
        return acked(route.id());
    }

    /** The registered agents of a kind a relay from {@code from} goes to: every one but the sender. */
    private List<Session> othersOfKind(Session from, AgentKind kind) {
        return registry.ofKind(kind).stream().filter(target -> target != from).toList();
    }

    /** The answer to a relay that went out: an {@code ack}, or nothing for a fire-and-forget relay (empty id). */
    private static Optional<Message> acked(String id) {
        return id.isEmpty() ? Optional.empty() : Optional.of(new Message.Ack(id));
    }

    /** The refusal of a relay to an unknown agent; without id for a fire-and-forget relay. */
    private static ErrorReply unknownAgent(String id, String to) {
        return nobody(id, "No agent '" + to + "' is registered.");
    }

    /**
     * The refusal of a relay to a kind no other agent registered as: answered rather than acked, since an ack would
     * tell the sender it reached someone.
     */
    private static ErrorReply noneOfKind(String id, AgentKind kind) {
        return nobody(id, "No other agent of kind '" + kind.name().toLowerCase(Locale.ROOT)
                + "' is registered, so nobody received the relay.");
    }

    private static ErrorReply nobody(String id, String text) {
        return id.isEmpty() ? ErrorReply.of(ErrorCode.UNKNOWN_AGENT, text) : ErrorReply.to(id, ErrorCode.UNKNOWN_AGENT, text);
    }

    /** Records a sensor signal; an error (without id) if the knowledge base refuses it. */
    Optional<Message> sensor(Session from, Message.SensorSignal signal) {
        try {
            runtime.signal(signal.from(from.agent()),
                    (millis, task) -> from.channel().eventLoop().schedule(task, millis, TimeUnit.MILLISECONDS));
            return Optional.empty();
        } catch (KnowledgeException | IllegalArgumentException e) {
            return Optional.of(ErrorReply.of(ErrorCode.REJECTED, "Sensor signal '" + signal.sensor() + "' from "
                    + from + " was refused: " + e.getMessage()));
        }
    }

    /** Cleans up after a closed connection: in-flight commands fail, subscriptions end, presence is retracted. */
    void connectionClosed(Session s) {
        if (s.agent().isEmpty()) {
            return;
        }
        commands.connectionClosed(s);
        knowledge.connectionClosed(s);
        boolean wasRegistered = registry.unregister(s);
        if (wasRegistered || registry.find(s.agent()).isEmpty()) { // not if a newer connection took the name
            runtime.retract(s.agent());
        }
        LOG.info("Agent {} disconnected{}.", s, wasRegistered ? "" : " (it was not registered)");
    }

    List<String> registeredAgents() {
        return registry.names();
    }
}
