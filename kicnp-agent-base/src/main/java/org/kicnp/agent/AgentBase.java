package org.kicnp.agent;

import static java.util.Objects.requireNonNull;

import java.io.IOException;
import java.time.Duration;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Supplier;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Value;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.ErrorCode;
import org.kicnp.protocol.FeedbackStage;
import org.kicnp.protocol.FrameText;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.Message.Command;
import org.kicnp.protocol.MessageCodec;
import org.kicnp.protocol.ProtocolException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The base class of every K-ICNP agent (the paper's "Agent Base Classes"). A subclass overrides what it needs —
 * {@link #capabilities()}, {@link #onCommand}, {@link #onRelay}, {@link #onChanged}, {@link #onConnected} — and
 * calls {@link #start()}. The base connects, authenticates, registers, keeps heartbeats, and after a lost
 * connection or a server restart reconnects with exponential backoff and jitter, registers again and renews its
 * subscriptions. Requests ({@link #query}, {@link #ask}, …) block the calling thread (cheap on a virtual thread)
 * and fail with a typed {@link AgentException}.
 *
 * <p>Threads: one virtual thread reads the connection; each command runs on its own virtual thread; relays and
 * change notifications are delivered in order on one event thread, through a queue of 10,000 that never makes the
 * reader wait: when it is full the oldest relay or change is dropped and counted ({@link #eventsDropped()}).
 */
public abstract class AgentBase implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(AgentBase.class);

    private final AgentOptions options;
    private final MessageCodec codec = new MessageCodec();
    private final Map<String, CompletableFuture<Message>> pending = new ConcurrentHashMap<>();
    private final Map<String, CommandTicket> tickets = new ConcurrentHashMap<>();
    /** The commands this (robot) agent runs, each through {@link #onCommand} and, on a cancel, {@link #onCancel}. */
    private final CommandRunner commands;
    private final Set<String> subscriptions = ConcurrentHashMap.newKeySet();
    private final AtomicLong ids = new AtomicLong();
    /**
     * Part of this agent object's command ids (its start time, base 36), so that the commands of two runs of one agent
     * — two {@code kicnp agent command} in a row — never share an id while the first is still in flight at the robot.
     */
    private final String commandIds = Long.toString(System.currentTimeMillis(), 36);
    /** Relays, changes and life-cycle callbacks, in order; never blocks the reader (the oldest are dropped). */
    private final EventQueue events;
    private final CountDownLatch firstOutcome = new CountDownLatch(1);
    private volatile Connection connection;
    private volatile boolean registered;
    /** Why the last connection attempt (or connection) failed, for a timeout's message; null: none failed. */
    private volatile String lastFailure;
    private volatile boolean closed;
    private volatile AgentException fatal;
    /** The error, answering no request, with which the server announced it closes the current connection. */
    private volatile Message.ErrorReply closing;
    private volatile Thread supervisor;

    protected AgentBase(AgentOptions options) {
        this.options = requireNonNull(options, "options");
        this.events = new EventQueue(options.name());
        this.commands = new CommandRunner(options.name(), this::onCommand, this::onCancel, this::send);
    }

    // ---- what a subclass overrides ----

    /** The frames describing what this agent can do, registered (all or none) each time it connects. */
    protected List<Frame> capabilities() {
        return List.of();
    }

    /** A command for this robot. Report through {@code handle}, now or later from any thread. */
    protected void onCommand(Command command, ActionHandle handle) {
        handle.failed("Agent '" + name() + "' does not take commands.");
    }

    /**
     * A request to stop a command this robot is running ({@code handle.command()}), from a user or service agent or
     * the platform. Stop the robot, then report through the handle — {@link ActionHandle#cancelled} for the usual
     * answer. By default the command is reported cancelled at once; the robot's own work on it is not interrupted,
     * so override this where the robot can stop. Runs on a virtual thread of its own. If it throws before the
     * command was reported done, the SDK reports it failed with "cancel failed: " and the exception's message — not
     * cancelled, since the robot may still be moving; the connection stays.
     */
    protected void onCancel(ActionHandle handle, String reason) {
        handle.cancelled(reason);
    }

    /** A message relayed from another agent. */
    protected void onRelay(Message.Relay relay) {
    }

    /** A change to a frame of a class this agent subscribed to. */
    protected void onChanged(Message.Changed change) {
    }

    /** Called (on the event thread) each time the agent is registered, first and after every reconnect. */
    protected void onConnected() {
    }

    /** Called (on the event thread) when a registered connection is lost; the agent is reconnecting. */
    protected void onDisconnected(String reason) {
    }

    /**
     * Called (on the event thread) when the server refuses to renew a subscription after a reconnect — the class was
     * destroyed while the agent was away, say. The subscription has ended: no {@link #onChanged} comes for it until
     * the agent subscribes again. The refusal is logged as a warning too.
     */
    protected void onSubscriptionRefused(String ofClass, RequestRefusedException reason) {
    }

    // ---- life cycle ----

    /** Starts connecting in the background; returns at once. Use {@link #awaitConnected} to wait. */
    public final synchronized void start() {
        if (supervisor != null) {
            throw new IllegalStateException("Agent '" + name() + "' was already started.");
        }
        supervisor = Thread.ofVirtual().name("agent-" + name()).start(this::supervise);
    }

    /** Starts the agent and waits until it is registered. */
    public final void startAndAwait(Duration timeout) {
        start();
        awaitConnected(timeout);
    }

    /**
     * Waits until the agent is registered.
     *
     * @throws AuthenticationException when the server refused the agent
     * @throws AgentTimeoutException when it is not registered within {@code timeout}
     */
    public final void awaitConnected(Duration timeout) {
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
                    + options.port() + " within " + words(timeout) + (last == null ? "." : "; the last attempt failed: "
                    + last + (last.endsWith(".") ? "" : ".")));
        }
    }

    public final String name() {
        return options.name();
    }

    /** A timeout as people write it: "15 s", "300 ms". */
    private static String words(Duration d) {
        long ms = d.toMillis();
        return ms % 1000 == 0 ? ms / 1000 + " s" : ms + " ms";
    }

    public final AgentKind kind() {
        return options.kind();
    }

    /** Whether the agent is registered right now. */
    public final boolean isConnected() {
        return registered;
    }

    /**
     * How many relays and change notifications were dropped, oldest first, because {@code onRelay} and
     * {@code onChanged} did not keep up: 10,000 were waiting for them (each drop logged at the first and every
     * 1,000th). The connection's reader never waits for them, so answers, commands and heartbeats are not held up.
     */
    public final long eventsDropped() {
        return events.dropped();
    }

    /** How many commands this robot agent took and has neither reported done nor lost with its connection. */
    public final int commandsInFlight() {
        return commands.inFlight();
    }

    /**
     * Why the agent stopped for good — refused by the server, or replaced by a newer connection under its name —
     * or empty while it runs or is reconnecting.
     */
    public final Optional<AgentException> stopped() {
        return Optional.ofNullable(fatal);
    }

    @Override public void close() {
        closed = true;
        Connection c = connection;
        if (c != null) {
            c.close();
        }
        Thread t = supervisor;
        if (t != null) {
            t.interrupt();
            try {
                t.join(Duration.ofSeconds(2));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        events.close();
        failPending(() -> new NotConnectedException("Agent '" + name() + "' was closed."));
    }

    // ---- what an agent can do ----

    /**
     * Reports a sensor signal; the server keeps the latest one as a {@code SensorSignal} frame.
     *
     * @throws IllegalArgumentException when a value is (or holds) NaN or an infinite number, which JSON cannot carry
     * @throws NotConnectedException when the agent is not connected (after a lost connection, until it has registered
     *     again; see {@link #isConnected()}): the reading is not sent, and a robot's sensing loop should catch this
     *     and go on with its next reading
     */
    public final void sensor(String sensor, Value... values) {
        send(new Message.SensorSignal(name(), sensor, List.of(values)));
    }

    /**
     * Reports a sensor signal that is good for {@code ttl} (1 ms to a day, whole milliseconds): unless a newer signal
     * of the same sensor comes first, the server then retracts it, with what the engine derived from it. For readings
     * a robot repeats while they hold (a face in view, an obstacle ahead): when the robot stops saying so, the
     * knowledge base stops believing it.
     *
     * @throws IllegalArgumentException when {@code ttl} is out of that range
     * @throws NotConnectedException when the agent is not connected, as {@link #sensor(String, Value...)}
     */
    public final void sensor(String sensor, Duration ttl, Value... values) {
        if (ttl.isNegative() || ttl.isZero() || ttl.compareTo(Duration.ofMillis(Message.SensorSignal.MAX_TTL_MS)) > 0
                || ttl.toNanos() % 1_000_000 != 0) {
            throw new IllegalArgumentException("The time to live of sensor '" + sensor
                    + "' must be a whole number of milliseconds from 1 ms to a day, not " + ttl + ".");
        }
        send(new Message.SensorSignal(name(), sensor, List.of(values), Optional.of(ttl.toMillis())));
    }

    /** Every instance of a class (and of the classes below it). */
    public final List<Frame> query(String ofClass) {
        Message.Frames f = (Message.Frames) request(new Message.Query(nextId(), ofClass));
        return parse(f.frames());
    }

    /** The effective value of a slot, inherited along IS-A; empty when it has none. */
    public final Optional<Value> ask(String frame, String slot) {
        return ((Message.Answer) request(new Message.Ask(nextId(), frame, slot))).value();
    }

    /**
     * Backward chaining on the server: every instance of a class that exists or could be derived, whose instance
     * slots hold the instances {@code bindings} names (slot → instance), each with its proof. Nothing is created.
     */
    public final List<Message.ProofNode> prove(String ofClass, Map<String, String> bindings) {
        return ((Message.Proofs) request(new Message.Prove(nextId(), ofClass, bindings))).proofs();
    }

    /** Why an instance exists, back to the stimuli. */
    public final Message.Reason why(String instance) {
        return ((Message.Explained) request(new Message.Why(nextId(), instance))).reason();
    }

    /**
     * Why a behavior frame has not fired, with the required slots {@code bindings} names held (slot → instance):
     * each slot's candidates, then each binding of them with what stops it. Nothing is created, no script runs.
     */
    public final Message.NotFired whyNot(String frame, Map<String, String> bindings) {
        return (Message.NotFired) request(new Message.WhyNot(nextId(), frame, bindings));
    }

    /** Adds or replaces an instance frame (stored as a RUNTIME frame). */
    public final void assertFrame(Frame instance) {
        request(new Message.Assert(nextId(), FrameText.toXml(instance)));
    }

    /** Adds or replaces instance frames (stored as RUNTIME frames) in one batch: the server takes all or none. */
    public final void assertFrames(List<Frame> instances) {
        if (instances.isEmpty()) {
            throw new IllegalArgumentException("Nothing to assert: no frames given.");
        }
        request(new Message.Assert(nextId(), FrameText.document(instances)));
    }

    /** Removes an instance frame. */
    public final void destroy(String frame) {
        request(new Message.Destroy(nextId(), frame));
    }

    /** Hears of every change to frames of a class through {@link #onChanged}; renewed after a reconnect. */
    public final void subscribe(String ofClass) {
        request(new Message.Subscribe(nextId(), ofClass));
        subscriptions.add(ofClass);
    }

    public final void unsubscribe(String ofClass) {
        subscriptions.remove(ofClass);
        request(new Message.Unsubscribe(nextId(), ofClass));
    }

    /**
     * Relays a message to one agent by name.
     *
     * @throws RequestRefusedException with {@code unknown_agent} when no such agent is registered
     */
    public final void relayTo(String agent, String subject, String body) {
        request(Message.Relay.toAgent(nextId(), name(), agent, subject, body));
    }

    /**
     * Relays a message to every registered agent of a kind (not to this one).
     *
     * @throws RequestRefusedException with {@code unknown_agent} when no other agent of that kind is registered, so
     *     nobody would receive it
     */
    public final void relayToKind(AgentKind kind, String subject, String body) {
        request(Message.Relay.toKind(nextId(), name(), kind, subject, body));
    }

    /**
     * Relays a message to one agent by name without waiting for the hub's {@code ack} (fire and forget: the relay
     * carries an empty id, so none is sent). A refusal, such as an unknown agent, arrives later as an error without
     * id and is logged. For a stream of messages where one round trip per message would be too slow.
     *
     * @throws NotConnectedException when the agent is not connected: the message is not sent
     */
    public final void tellTo(String agent, String subject, String body) {
        send(Message.Relay.toAgent("", name(), agent, subject, body));
    }

    /** Relays a message to every registered agent of a kind (not to this one), fire and forget like {@link #tellTo}. */
    public final void tellToKind(AgentKind kind, String subject, String body) {
        send(Message.Relay.toKind("", name(), kind, subject, body));
    }

    /** Sends a command to a robot through the hub (what a user agent does); follow it with the ticket. */
    public final CommandTicket command(String robot, String action, Map<String, String> args) {
        Command c = new Command(commandId(), robot, action, args);
        CommandTicket ticket = new CommandTicket(c);
        tickets.put(c.id(), ticket);
        try {
            request(c);
        } catch (AgentException e) {
            tickets.remove(c.id());
            throw e;
        }
        return ticket;
    }

    /**
     * Asks that a command in flight on a robot be stopped (a user or service agent: an operator may stop a command
     * whoever sent it). The outcome arrives as the command's last feedback, on its {@link CommandTicket} for the
     * agent that sent it.
     *
     * @throws RequestRefusedException when no such command is in flight, or this agent may not cancel
     */
    public final void cancel(String robot, String commandId, String reason) {
        request(new Message.Cancel(nextId(), robot, commandId, reason));
    }

    /** Sends frames to the server (a peer agent's push); stored all or none. */
    public final void push(List<Frame> frames) {
        request(new Message.Push(nextId(), FrameText.toXml(frames)));
    }

    /** Fetches a subtree (or, without a root, the whole knowledge base) from the server, parents first. */
    public final List<Frame> pull(Optional<String> root) {
        return parse(((Message.Frames) request(new Message.Pull(nextId(), root))).frames());
    }

    // ---- internals ----

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
        c.send(new Message.Hello("hello", name(), kind(), options.token()));
        Message auth = awaitDirect(c, "hello");
        if (auth instanceof Message.AuthResult r && !r.accepted()) {
            String reason = r.reason().orElse("no reason given");
            throw new AuthenticationException("Server refused agent '" + name() + "': " + reason
                    + (reason.endsWith(".") ? "" : "."));
        }
        if (!(auth instanceof Message.AuthResult)) {
            throw new AgentException("Expected auth_result, got " + auth + ".");
        }
        c.send(new Message.Register("register", FrameText.toXml(capabilities())));
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
        events.callback(this::onConnected);
    }

    /**
     * Renews a subscription on a new connection without waiting for the answer (the read loop, which reads it, has
     * not started yet); a refusal ends the subscription, logged and reported through {@link #onSubscriptionRefused}.
     */
    private void resubscribe(Connection c, String ofClass) throws IOException {
        String id = "resubscribe-" + nextId();
        CompletableFuture<Message> answer = new CompletableFuture<>();
        pending.put(id, answer);
        answer.thenAccept(m -> {
            if (m instanceof Message.ErrorReply e) {
                subscriptions.remove(ofClass);
                LOG.warn("Agent '{}': the server refused to renew its subscription to '{}' after a reconnect ({}): {}",
                        name(), ofClass, e.code().name().toLowerCase(Locale.ROOT), e.message());
                RequestRefusedException reason = new RequestRefusedException(e.code(), e.message());
                events.callback(() -> onSubscriptionRefused(ofClass, reason));
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
                default -> { } // heartbeats before registration
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
        while (!closed) {
            Message m = c.read();
            switch (m) {
                case Message.Command cmd -> commands.command(cmd);
                case Message.Feedback f -> {
                    CommandTicket t = f.stage().terminal() ? tickets.remove(f.id()) : tickets.get(f.id());
                    if (t != null) {
                        t.received(f);
                    }
                }
                case Message.Relay r -> events.deliver(() -> onRelay(r));
                case Message.Changed ch -> events.deliver(() -> onChanged(ch));
                case Message.Heartbeat h -> { }
                case Message.ErrorReply e when e.code() == ErrorCode.SUPERSEDED ->
                        throw new AuthenticationException("Agent '" + name() + "' stops: " + e.message());
                case Message.ErrorReply e when e.id().isEmpty() -> {
                    LOG.warn("Agent '{}': server says {}: {}", name(), e.code(), e.message());
                    if (e.code().closesConnection()) {
                        closing = e;
                    }
                }
                case Message.ErrorReply e -> complete(e.id().get(), e);
                case Message.Ack a -> complete(a.id(), a);
                case Message.Frames f -> complete(f.id(), f);
                case Message.Answer a -> complete(a.id(), a);
                case Message.Proofs p -> complete(p.id(), p);
                case Message.Explained x -> complete(x.id(), x);
                case Message.NotFired x -> complete(x.id(), x);
                case Message.AuthResult a -> complete(a.id(), a);
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
    }

    private void complete(String id, Message answer) {
        CompletableFuture<Message> f = pending.remove(id);
        if (f != null) {
            f.complete(answer);
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
            failPending(() -> new RequestRefusedException(why.code(), why.message()));
        } else {
            String reason = "Agent '" + name() + "' lost its connection"
                    + (why == null ? "." : ": the server closed it (" + why.code().name().toLowerCase(Locale.ROOT)
                    + "): " + why.message());
            failPending(() -> new NotConnectedException(reason));
        }
        // The server sends feedback to the connection that issued a command; a new connection will not hear it.
        tickets.forEach((id, t) -> t.received(new Message.Feedback(id, t.command().robot(), FeedbackStage.FAILED,
                Optional.empty(), "the connection to the gateway was lost before command '" + id + "' ended")));
        tickets.clear();
        // The server fails the commands this robot runs, too: cancel them, so that the robot stops and its program hears.
        commands.connectionLost(closed ? "agent '" + name() + "' was closed" : "the connection to the gateway was lost");
        if (was && !closed) {
            events.callback(() -> onDisconnected("connection lost"));
        }
    }

    private void failPending(Supplier<AgentException> failure) {
        pending.forEach((id, f) -> f.completeExceptionally(failure.get()));
        pending.clear();
    }

    /**
     * Sends a message that expects no answer.
     *
     * @throws NotConnectedException when the agent is not connected, or the connection fails while sending (it is
     *     then closed, and the agent reconnects)
     */
    private void send(Message m) {
        Connection c = connection;
        if (c == null) {
            throw new NotConnectedException("Agent '" + name() + "' is not connected; " + m.getClass().getSimpleName()
                    + " not sent.");
        }
        try {
            c.send(m);
        } catch (IOException e) {
            c.close();
            throw new NotConnectedException("Agent '" + name() + "' could not send: " + e.getMessage());
        }
    }

    private Message request(Message.Request r) {
        CompletableFuture<Message> answer = new CompletableFuture<>();
        pending.put(r.id(), answer);
        try {
            send(r);
            Message m = answer.get(options.requestTimeout().toMillis(), TimeUnit.MILLISECONDS);
            if (m instanceof Message.ErrorReply e) {
                throw new RequestRefusedException(e.code(), e.message());
            }
            return m;
        } catch (TimeoutException e) {
            throw new AgentTimeoutException("The server did not answer " + r.getClass().getSimpleName() + " '" + r.id()
                    + "' within " + words(options.requestTimeout()) + ".");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AgentException("Interrupted while waiting for the answer to '" + r.id() + "'.", e);
        } catch (ExecutionException e) {
            throw e.getCause() instanceof AgentException a ? a : new AgentException(e.getCause().getMessage(), e);
        } finally {
            pending.remove(r.id());
        }
    }

    private String nextId() {
        return Long.toString(ids.incrementAndGet());
    }

    /**
     * The agent's name, the time this object was made and a counter, so two runs of one agent never share an id at a
     * robot. A name so long that the id would pass {@link Message#MAX_NAME_LENGTH} gives only its beginning (not
     * half a surrogate pair): the server keys commands by robot and id and refuses one already in flight, so a clash
     * of two such agents is a refusal, never a mix-up.
     */
    private String commandId() {
        String tail = "-" + commandIds + "-" + nextId();
        int cut = Math.min(name().length(), Message.MAX_NAME_LENGTH - tail.length());
        if (cut > 0 && Character.isHighSurrogate(name().charAt(cut - 1))) {
            cut--;
        }
        return name().substring(0, cut) + tail;
    }

    private static List<Frame> parse(List<String> xml) {
        KnowledgeBase context = KnowledgeBase.create();
        // One set: an instance's list items take their type from its class, which travels in another text.
        return FrameText.parse(xml, i -> "server #" + (i + 1), context);
    }
}
