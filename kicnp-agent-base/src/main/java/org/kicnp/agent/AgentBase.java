package org.kicnp.agent;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Value;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.FrameText;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.Message.Command;

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
    private final AgentOptions options;
    /** The answers and command feedback this agent awaits, by id; also where request ids come from. */
    private final PendingRequests pending;
    /** The commands this (robot) agent runs, each through {@link #onCommand} and, on a cancel, {@link #onCancel}. */
    private final CommandRunner commands;
    /** The classes this agent subscribed to; the supervisor renews them after a reconnect. */
    private final Set<String> subscriptions = ConcurrentHashMap.newKeySet();
    /**
     * Part of this agent object's command ids (its start time, base 36), so that the commands of two runs of one agent
     * — two {@code kicnp agent command} in a row — never share an id while the first is still in flight at the robot.
     */
    private final String commandIds = Long.toString(System.currentTimeMillis(), 36);
    /** Relays, changes and life-cycle callbacks, in order; never blocks the reader (the oldest are dropped). */
    private final EventQueue events;
    /** The connection's life: connect, register, heartbeats, read, reconnect. */
    private final Supervisor supervisor;

    protected AgentBase(AgentOptions options) {
        this.options = requireNonNull(options, "options");
        this.pending = new PendingRequests(options.requestTimeout());
        this.events = new EventQueue(options.name());
        this.commands = new CommandRunner(options.name(), this::onCommand, this::onCancel, this::send);
        this.supervisor = new Supervisor(this, options, pending, commands, events, subscriptions);
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
        supervisor.start();
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
        supervisor.awaitConnected(timeout);
    }

    public final String name() {
        return options.name();
    }

    /** A timeout as people write it: "15 s", "300 ms". */
    static String words(Duration d) {
        long ms = d.toMillis();
        return ms % 1000 == 0 ? ms / 1000 + " s" : ms + " ms";
    }

    public final AgentKind kind() {
        return options.kind();
    }

    /** Whether the agent is registered right now. */
    public final boolean isConnected() {
        return supervisor.isRegistered();
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
        return supervisor.stopped();
    }

    @Override public void close() {
        supervisor.close();
        events.close();
        pending.failAll(() -> new NotConnectedException("Agent '" + name() + "' was closed."));
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
        return snapshot(ofClass).frames();
    }

    /**
     * Every instance of a class (and of the classes below it), as {@link #query}, with the server's clock when it read
     * them: the clock of the times the frames hold (a sensor signal's {@code time} and {@code expires}), which need
     * not be this machine's.
     */
    public final Snapshot snapshot(String ofClass) {
        Message.Frames f = (Message.Frames) request(new Message.Query(nextId(), ofClass));
        return new Snapshot(parse(f.frames()), f.time());
    }

    /**
     * What {@link #snapshot} answers: the frames, and the server's clock (epoch milliseconds) when it read them, empty
     * from a server that does not say (before protocol.md gave {@code frames} its {@code time}).
     */
    public record Snapshot(List<Frame> frames, Optional<Long> serverTime) {
        public Snapshot {
            frames = List.copyOf(frames);
            requireNonNull(serverTime, "serverTime");
        }
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
     * each slot's candidates, then each binding of them with what stops it. Nothing is created (script conditions
     * run, as on matching, and cannot change anything).
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
        pending.track(ticket);
        try {
            request(c);
        } catch (AgentException e) {
            pending.untrack(c.id());
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

    /** Sends a message that expects no answer; see {@link Supervisor#send}. */
    private void send(Message m) {
        supervisor.send(m);
    }

    private Message request(Message.Request r) {
        return pending.request(r, this::send);
    }

    private String nextId() {
        return pending.nextId();
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
