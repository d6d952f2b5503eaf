package org.kicnp.agent;

import java.io.IOException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeUnit;
import org.kicnp.protocol.ErrorCode;
import org.kicnp.protocol.FrameText;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.MessageCodec;
import org.kicnp.protocol.ProtocolException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Keeps an {@link AgentBase} connected, on one virtual thread: connects, says hello and registers, renews the agent's
 * subscriptions, sends heartbeats, reads what the server sends and routes it — answers and feedback to the
 * {@link PendingRequests}, commands and cancels to the {@link CommandRunner}, relays and changes to the
 * {@link EventQueue} — and after a lost connection or a server restart connects again with exponential backoff and
 * equal jitter, until the agent is closed or stops for good (refused, or replaced by a newer connection).
 *
 * <p>Kept apart from {@link AgentBase}, which is the API a robot developer sees and subclasses, because this is the
 * connection's life: its state (the connection, whether registered, why it stopped) changes only here, and the agent
 * only asks it to send and to report.
 */
final class Supervisor {
    /** The agent's own logger category, so that logging set up for the SDK still covers these lines. */
    private static final Logger LOG = LoggerFactory.getLogger(AgentBase.class);

    private final AgentBase agent;
    private final AgentOptions options;
    private final MessageCodec codec = new MessageCodec();
    private final PendingRequests pending;
    private final CommandRunner commands;
    private final EventQueue events;
    /** The classes the agent subscribed to, renewed on each new connection (the agent adds and removes them). */
    private final Set<String> subscriptions;
    private final CountDownLatch firstOutcome = new CountDownLatch(1);
    private volatile Connection connection;
    private volatile boolean registered;
    /** Why the last connection attempt (or connection) failed, for a timeout's message; null: none failed. */
    private volatile String lastFailure;
    private volatile boolean closed;
    private volatile AgentException fatal;
    /** The error, answering no request, with which the server announced it closes the current connection. */
    private volatile Message.ErrorReply closing;
    private volatile Thread thread;
    /** Messages read while waiting for the answer to the hello or the register: handled once registered. */
    private final List<Message> early = new ArrayList<>();

    Supervisor(AgentBase agent, AgentOptions options, PendingRequests pending, CommandRunner commands,
               EventQueue events, Set<String> subscriptions) {
        this.agent = agent;
        this.options = options;
        this.pending = pending;
        this.commands = commands;
        this.events = events;
        this.subscriptions = subscriptions;
    }

    /** Starts connecting in the background. */
    synchronized void start() {
        if (thread != null) {
            throw new IllegalStateException("Agent '" + name() + "' was already started.");
        }
        thread = Thread.ofVirtual().name("agent-" + name()).start(this::supervise);
    }

    /** As {@link AgentBase#awaitConnected}. */
    void awaitConnected(Duration timeout) {
        long deadline = System.nanoTime() + timeout.toNanos();
        try {
            firstOutcome.await(timeout.toMillis(), TimeUnit.MILLISECONDS);
            while (!registered && fatal == null && !closed && System.nanoTime() < deadline) {
                Thread.sleep(10);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        if (fatal != null) {
            throw fatal;
        }
        if (!registered) {
            String last = lastFailure;
            throw new AgentTimeoutException("Agent '" + name() + "' was not registered with " + options.host() + ":"
                    + options.port() + " within " + AgentBase.words(timeout) + (last == null ? "."
                    : "; the last attempt failed: " + last + (last.endsWith(".") ? "" : ".")));
        }
    }

    /** Whether the agent is registered right now. */
    boolean isRegistered() {
        return registered;
    }

    /** Why the agent stopped for good, or empty while it runs or is reconnecting. */
    Optional<AgentException> stopped() {
        return Optional.ofNullable(fatal);
    }

    /** Stops for good: closes the connection and waits (up to 2 s) for the supervising thread to end. */
    void close() {
        closed = true;
        Connection c = connection;
        if (c != null) {
            c.close();
        }
        Thread t = thread;
        if (t != null) {
            t.interrupt();
            try {
                t.join(Duration.ofSeconds(2));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    /**
     * Sends a message that expects no answer.
     *
     * @throws NotConnectedException when the agent is not connected, or the connection fails while sending (it is
     *     then closed, and the agent reconnects)
     */
    void send(Message m) {
        Connection c = connection;
        if (c == null) {
            throw new NotConnectedException("Agent '" + name() + "' is not connected; " + m.getClass().getSimpleName()
                    + " not sent.");
        }
        try {
            c.send(m);
        } catch (IOException e) {
            c.close();
            throw new NotConnectedException("Agent '" + name() + "' could not send: " + e.getMessage(), e);
        }
    }

    private String name() {
        return options.name();
    }

    private void supervise() {
        Duration delay = options.backoffInitial();
        while (!closed) {
            AgentException stop = null;
            try (Connection c = Connection.open(options, codec)) {
                handshake(c);
                delay = options.backoffInitial();
                readLoop(c);
            } catch (AuthenticationException e) {
                stop = e;
                LOG.error("Agent '{}' stops: {}", name(), e.getMessage());
                return;
            } catch (IOException | ProtocolException | NotConnectedException e) {
                if (closed) {
                    return;
                }
                lastFailure = e.getMessage() == null ? e.toString() : e.getMessage();
                LOG.info("Agent '{}' lost its connection to {}:{} ({}); reconnecting.", name(), options.host(),
                        options.port(), e.getMessage() == null ? e.toString() : e.getMessage());
            } catch (RuntimeException e) { // a bug in a subclass (say, in capabilities()) or a server we do not understand
                stop = e instanceof AgentException a ? a : new AgentException("Agent '" + name() + "' stops: " + e, e);
                LOG.error("Agent '{}' stops.", name(), e);
                return;
            } finally {
                lost();
                if (stop != null) { // only now: whoever sees the agent stopped sees it disconnected too
                    fatal = stop;
                    firstOutcome.countDown();
                }
            }
            try {
                long ms = delay.toMillis();
                Thread.sleep(ms / 2 + ThreadLocalRandom.current().nextLong(ms / 2 + 1)); // "equal jitter"
            } catch (InterruptedException e) {
                return;
            }
            delay = delay.multipliedBy(2).compareTo(options.backoffMax()) > 0 ? options.backoffMax() : delay.multipliedBy(2);
        }
    }

    private void handshake(Connection c) throws IOException {
        early.clear(); // what an earlier connection left
        c.send(new Message.Hello("hello", name(), options.kind(), options.token()));
        Message auth = awaitDirect(c, "hello");
        if (auth instanceof Message.AuthResult r && !r.accepted()) {
            String reason = r.reason().orElse("no reason given");
            throw new AuthenticationException("Server refused agent '" + name() + "': " + reason
                    + (reason.endsWith(".") ? "" : "."));
        }
        if (!(auth instanceof Message.AuthResult)) {
            throw new AgentException("Expected auth_result, got " + auth + ".");
        }
        c.send(new Message.Register("register", FrameText.toXml(agent.capabilities())));
        if (awaitDirect(c, "register") instanceof Message.ErrorReply e) {
            throw new AuthenticationException("Server refused to register agent '" + name() + "': " + e.message());
        }
        connection = c;
        for (String ofClass : subscriptions) {
            resubscribe(c, ofClass);
        }
        registered = true;
        firstOutcome.countDown();
        startHeartbeats(c);
        LOG.info("Agent '{}' registered with {}:{}.", name(), options.host(), options.port());
        events.callback(agent::onConnected);
    }

    /**
     * Renews a subscription on a new connection without waiting for the answer (the read loop, which reads it, has
     * not started yet); a refusal ends the subscription, logged and reported through {@link AgentBase#onSubscriptionRefused}.
     */
    private void resubscribe(Connection c, String ofClass) throws IOException {
        String id = "resubscribe-" + pending.nextId();
        CompletableFuture<Message> answer = pending.expect(id);
        answer.thenAccept(m -> {
            if (m instanceof Message.ErrorReply e) {
                subscriptions.remove(ofClass);
                LOG.warn("Agent '{}': the server refused to renew its subscription to '{}' after a reconnect ({}): {}",
                        name(), ofClass, e.code().name().toLowerCase(Locale.ROOT), e.message());
                RequestRefusedException reason = new RequestRefusedException(e.code(), e.message());
                events.callback(() -> agent.onSubscriptionRefused(ofClass, reason));
            }
        });
        c.send(new Message.Subscribe(id, ofClass));
    }

    private Message awaitDirect(Connection c, String id) throws IOException {
        while (true) {
            Message m = c.read();
            switch (m) {
                case Message.AuthResult r when r.id().equals(id) -> {
                    return r;
                }
                case Message.Ack a when a.id().equals(id) -> {
                    return a;
                }
                case Message.ErrorReply e when e.id().isEmpty() -> handshakeError(e, id);
                case Message.ErrorReply e when e.id().get().equals(id) -> {
                    if (id.equals("hello")) {
                        throw new AuthenticationException("Server refused agent '" + name() + "': " + e.message());
                    }
                    return e;
                }
                case Message.Heartbeat h -> { }
                default -> early.add(m); // for the read loop, once registered
            }
        }
    }

    /**
     * An error answering no request while the agent says hello or registers. Only {@code not_authenticated} refuses
     * the agent, which then stops; any other is about this connection (a heartbeat timeout, an overloaded or failing
     * server): it is logged, and when the server closes the connection over it the agent connects again, as after
     * any lost connection, rather than stopping for good over something a retry may not meet.
     *
     * @throws AuthenticationException on {@code not_authenticated}
     * @throws NotConnectedException on an error that closes the connection
     */
    private void handshakeError(Message.ErrorReply e, String awaiting) {
        if (e.code() == ErrorCode.NOT_AUTHENTICATED) {
            throw new AuthenticationException("Server refused agent '" + name() + "': " + e.message());
        }
        String code = e.code().name().toLowerCase(Locale.ROOT);
        LOG.warn("Agent '{}': server says {} while awaiting the answer to its {}: {}", name(), code, awaiting,
                e.message());
        if (e.code().closesConnection()) {
            throw new NotConnectedException("Agent '" + name() + "' was not registered: the server closed the "
                    + "connection (" + code + "): " + e.message());
        }
    }

    private void startHeartbeats(Connection c) {
        Thread.ofVirtual().name("agent-heartbeat-" + name()).start(() -> {
            try {
                while (c.isOpen() && !closed) {
                    Thread.sleep(options.heartbeatInterval());
                    c.send(new Message.Heartbeat(System.currentTimeMillis()));
                }
            } catch (IOException | InterruptedException e) {
                // The connection is gone; the read loop notices and reconnects.
            }
        });
    }

    private void readLoop(Connection c) throws IOException {
        // First what the server sent before its answer to the register: nothing from a server of this protocol, but
        // an older one could queue a command or a relay ahead of it (docs/protocol.md, "Connection life cycle").
        for (Message m : early) {
            handle(m);
        }
        early.clear();
        while (!closed) {
            handle(c.read());
        }
    }

    private void handle(Message m) {
        switch (m) {
            case Message.Command cmd -> commands.command(cmd);
            case Message.Feedback f -> pending.feedback(f);
            case Message.Relay r -> events.deliver(() -> agent.onRelay(r));
            case Message.Changed ch -> events.deliver(() -> agent.onChanged(ch));
            case Message.Heartbeat h -> { }
            case Message.ErrorReply e when e.code() == ErrorCode.SUPERSEDED ->
                    throw new AuthenticationException("Agent '" + name() + "' stops: " + e.message());
            case Message.ErrorReply e when e.id().isEmpty() -> {
                LOG.warn("Agent '{}': server says {}: {}", name(), e.code(), e.message());
                if (e.code().closesConnection()) {
                    closing = e;
                }
            }
            case Message.ErrorReply e -> pending.complete(e.id().get(), e);
            case Message.Ack a -> pending.complete(a.id(), a);
            case Message.Frames f -> pending.complete(f.id(), f);
            case Message.Answer a -> pending.complete(a.id(), a);
            case Message.Proofs p -> pending.complete(p.id(), p);
            case Message.Explained x -> pending.complete(x.id(), x);
            case Message.NotFired x -> pending.complete(x.id(), x);
            case Message.AuthResult a -> pending.complete(a.id(), a);
            case Message.Hello h -> LOG.warn("Agent '{}' ignores an unexpected {}.", name(), h);
            case Message.Register x -> LOG.warn("Agent '{}' ignores an unexpected register.", name());
            case Message.SensorSignal x -> LOG.warn("Agent '{}' ignores an unexpected sensor signal.", name());
            case Message.Query x -> LOG.warn("Agent '{}' ignores an unexpected query.", name());
            case Message.Ask x -> LOG.warn("Agent '{}' ignores an unexpected ask.", name());
            case Message.Assert x -> LOG.warn("Agent '{}' ignores an unexpected assert.", name());
            case Message.Destroy x -> LOG.warn("Agent '{}' ignores an unexpected destroy.", name());
            case Message.Subscribe x -> LOG.warn("Agent '{}' ignores an unexpected subscribe.", name());
            case Message.Unsubscribe x -> LOG.warn("Agent '{}' ignores an unexpected unsubscribe.", name());
            case Message.Push x -> LOG.warn("Agent '{}' ignores an unexpected push.", name());
            case Message.Pull x -> LOG.warn("Agent '{}' ignores an unexpected pull.", name());
            case Message.Cancel x -> commands.cancel(x);
            case Message.Prove x -> LOG.warn("Agent '{}' ignores an unexpected prove.", name());
            case Message.Why x -> LOG.warn("Agent '{}' ignores an unexpected why.", name());
            case Message.WhyNot x -> LOG.warn("Agent '{}' ignores an unexpected why_not.", name());
        }
    }

    private void lost() {
        boolean was = registered;
        registered = false;
        connection = null;
        Message.ErrorReply why = closing;
        closing = null;
        if (why != null && why.code() == ErrorCode.FRAME_TOO_LARGE) {
            // The request in flight was too long for the server, which said so and closed: that is its answer.
            pending.failAll(() -> new RequestRefusedException(why.code(), why.message()));
        } else {
            String reason = "Agent '" + name() + "' lost its connection"
                    + (why == null ? "." : ": the server closed it (" + why.code().name().toLowerCase(Locale.ROOT)
                    + "): " + why.message());
            pending.failAll(() -> new NotConnectedException(reason));
        }
        // The server sends feedback to the connection that issued a command; a new connection will not hear it.
        pending.commandsLost();
        // The server fails the commands this robot runs, too: cancel them, so that the robot stops and its program hears.
        commands.connectionLost(closed ? "agent '" + name() + "' was closed" : "the connection to the gateway was lost");
        if (was && !closed) {
            events.callback(() -> agent.onDisconnected("connection lost"));
        }
    }
}
