package org.kicnp.protocol;

import static java.util.Objects.requireNonNull;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Pattern;
import org.kicnp.core.Value;

/**
 * The closed set of K-ICNP wire messages, one record per message type of {@code docs/protocol.md}. Records check
 * their members when built, so a decoded message is already well-formed; the gateway and the SDK switch over this
 * interface exhaustively. Frames travel as the paper's XML text; slot values as {@link Value}s.
 */
public sealed interface Message {

    /** Letters, digits, {@code _} and {@code -}, starting with a letter or {@code _}: the names of agents. */
    Pattern NAME = Pattern.compile("[\\p{L}_][\\p{L}\\p{N}_\\-]*");

    /**
     * The most characters (UTF-16 units, as {@link String#length()} counts them) a name (of an agent, a robot, a
     * sensor), a command's action, a request's id (and a command id a robot or a cancel quotes), a relay's subject or
     * a class name a request asks about may have: far below the frame's limit, so that one member cannot fill a frame,
     * the knowledge base's frame names, a table keyed by ids or an error that quotes it. Values, bodies, frames and
     * command arguments are bounded by the frame alone.
     */
    int MAX_NAME_LENGTH = 256;

    /** A message that expects an answer echoing its {@link #id()}. */
    sealed interface Request extends Message permits Hello, Register, Relay, Command, Query, Ask, Assert, Destroy,
            Subscribe, Unsubscribe, Push, Pull, Prove, Why, WhyNot, Cancel {
        /** The correlation id, chosen by the sender and echoed by the answer. */
        String id();
    }

    /** Authenticates a connection: the first message an agent sends. */
    record Hello(String id, String agent, AgentKind kind, String token) implements Request {
        public Hello {
            checkLimited(id, "id");
            requireNonNull(kind, "kind");
            requireNonNull(token, "token");
            checkName(agent, "agent");
        }

        @Override public String toString() {
            return "Hello[id=" + id + ", agent=" + agent + ", kind=" + kind + ", token=***]";
        }
    }

    /** The answer to {@link Hello}; a refusal says why in {@code reason}. */
    record AuthResult(String id, boolean accepted, String server, Optional<String> reason) implements Message {
        public AuthResult {
            requireNonNull(id, "id");
            requireNonNull(server, "server");
            requireNonNull(reason, "reason");
        }
    }

    /** Tells the platform what the agent can do: capability frames as XML. */
    record Register(String id, List<String> capabilities) implements Request {
        public Register {
            checkLimited(id, "id");
            capabilities = List.copyOf(capabilities);
        }
    }

    /** The plain answer to a request that succeeded. */
    record Ack(String id) implements Message {
        public Ack {
            requireNonNull(id, "id");
        }
    }

    /** Keeps an idle connection alive; {@code time} is the sender's clock in epoch milliseconds. */
    record Heartbeat(long time) implements Message {
    }

    /** A message from one agent to another agent, or to every agent of a kind, through the hub. */
    record Relay(String id, String from, Optional<String> toAgent, Optional<AgentKind> toKind, String subject,
                 String body) implements Request {
        public Relay {
            checkLimited(id, "id");
            requireNonNull(from, "from");
            requireNonNull(toAgent, "toAgent");
            requireNonNull(toKind, "toKind");
            checkLimited(subject, "subject");
            requireNonNull(body, "body");
            if (toAgent.isPresent() == toKind.isPresent()) {
                throw new IllegalArgumentException("A relay needs exactly one of toAgent and toKind.");
            }
            checkLength(from, "from");
            toAgent.ifPresent(to -> checkLength(to, "toAgent"));
        }

        /** A relay to one agent by name. */
        public static Relay toAgent(String id, String from, String agent, String subject, String body) {
            return new Relay(id, from, Optional.of(agent), Optional.empty(), subject, body);
        }

        /** A relay to every registered agent of a kind. */
        public static Relay toKind(String id, String from, AgentKind kind, String subject, String body) {
            return new Relay(id, from, Optional.empty(), Optional.of(kind), subject, body);
        }

        /** The same relay stamped with the sender the server authenticated. */
        public Relay from(String sender) {
            return new Relay(id, sender, toAgent, toKind, subject, body);
        }
    }

    /** An action for a robot: the instruction the platform converts into the robot's local command (section 3.3). */
    record Command(String id, String robot, String action, Map<String, String> args) implements Request {
        public Command {
            checkLimited(id, "id");
            checkName(robot, "robot");
            requireNonNull(action, "action");
            if (action.isBlank()) {
                throw new IllegalArgumentException("A command needs an action.");
            }
            checkLength(action, "action");
            args = Map.copyOf(args);
        }
    }

    /**
     * Asks that a command in flight be stopped (a user or service agent to the server; the server to the robot's
     * agent, with the same command id). The robot decides how to stop and answers with the command's last feedback,
     * {@code failed} with a reason that starts with "cancelled" (or {@code ended}, when it had already finished; or
     * {@code failed} with "cancel failed", when the robot's agent could not stop it and the robot may still move).
     */
    record Cancel(String id, String robot, String command, String reason) implements Request {
        public Cancel {
            checkLimited(id, "id");
            checkName(robot, "robot");
            checkLimited(command, "command");
            requireNonNull(reason, "reason");
        }
    }

    /** A robot's report on a command: started, progress, ended with a result, or failed with a reason. */
    record Feedback(String id, String robot, FeedbackStage stage, Optional<Double> progress, String detail)
            implements Message {
        public Feedback {
            checkLimited(id, "id");
            requireNonNull(robot, "robot");
            requireNonNull(stage, "stage");
            requireNonNull(progress, "progress");
            requireNonNull(detail, "detail");
            progress.ifPresent(p -> {
                if (!(p >= 0.0 && p <= 1.0)) { // NaN too
                    throw new IllegalArgumentException("The progress of command '" + id
                            + "' must be a fraction from 0.0 to 1.0, not " + p + ".");
                }
            });
        }

        /** The same feedback stamped with the robot the server authenticated. */
        public Feedback from(String sender) {
            return new Feedback(id, sender, stage, progress, detail);
        }
    }

    /**
     * A signal detected by a sensor; {@code source} is stamped by the server with the sending agent's name. With
     * {@code ttlMs}, the reading is good for that many milliseconds: unless a newer signal of the same sensor comes
     * first, the server then takes it out of the knowledge base (and what was derived from it), so a slot condition
     * never rests on a reading the robot stopped giving. Without it, the reading holds until the next one or until
     * the agent goes away.
     */
    record SensorSignal(String source, String sensor, List<Value> values, Optional<Long> ttlMs) implements Message {
        /** The longest time to live a signal may ask for: one day. */
        public static final long MAX_TTL_MS = 86_400_000L;

        public SensorSignal {
            requireNonNull(source, "source");
            checkName(sensor, "sensor");
            values = List.copyOf(values);
            for (int i = 0; i < values.size(); i++) {
                Optional<Double> bad = nonFinite(values.get(i));
                if (bad.isPresent()) {
                    throw new IllegalArgumentException("Sensor '" + sensor + "' value #" + (i + 1) + " is " + bad.get()
                            + ", which JSON cannot carry as a number: send a finite number, or a string or boolean "
                            + "that says what the reading means.");
                }
            }
            requireNonNull(ttlMs, "ttlMs");
            ttlMs.ifPresent(ttl -> {
                if (ttl < 1 || ttl > MAX_TTL_MS) {
                    throw new IllegalArgumentException("The time to live of sensor '" + sensor + "' must be 1 to "
                            + MAX_TTL_MS + " ms, not " + ttl + ".");
                }
            });
        }

        /** The first NaN or infinite number in a value, at any depth of lists. */
        private static Optional<Double> nonFinite(Value v) {
            return switch (v) {
                case Value.Real r when !Double.isFinite(r.value()) -> Optional.of(r.value());
                case Value.Lst l -> l.items().stream().map(SensorSignal::nonFinite).flatMap(Optional::stream).findFirst();
                default -> Optional.empty();
            };
        }

        /** A signal that holds until the next one of the same sensor (no time to live). */
        public SensorSignal(String source, String sensor, List<Value> values) {
            this(source, sensor, values, Optional.empty());
        }

        /** The same signal stamped with the agent the server authenticated. */
        public SensorSignal from(String sender) {
            return new SensorSignal(sender, sensor, values, ttlMs);
        }
    }

    /** Asks for every instance of a class (and of the classes below it). */
    record Query(String id, String ofClass) implements Request {
        public Query {
            checkLimited(id, "id");
            checkLimited(ofClass, "ofClass");
        }
    }

    /**
     * Frames as XML text: the answer to {@link Query} and {@link Pull}. {@code time} is the server's clock (epoch
     * milliseconds) when it read them, the clock its frames' times ({@code time}, {@code expires}, {@code since}) are
     * on, so an agent whose own clock differs can tell what was left of a time to live; empty from servers before it.
     */
    record Frames(String id, List<String> frames, Optional<Long> time) implements Message {
        public Frames {
            requireNonNull(id, "id");
            frames = List.copyOf(frames);
            requireNonNull(time, "time");
        }
    }

    /** Asks for the effective value of one slot of one frame, inherited along IS-A. */
    record Ask(String id, String frame, String slot) implements Request {
        public Ask {
            checkLimited(id, "id");
            requireNonNull(frame, "frame");
            requireNonNull(slot, "slot");
        }
    }

    /** The answer to {@link Ask}; empty when the slot has no value. */
    record Answer(String id, Optional<Value> value) implements Message {
        public Answer {
            requireNonNull(id, "id");
            requireNonNull(value, "value");
        }
    }

    /** Adds or replaces one instance frame, given as XML. */
    record Assert(String id, String frame) implements Request {
        public Assert {
            checkLimited(id, "id");
            requireNonNull(frame, "frame");
        }
    }

    /** Removes a frame by name. */
    record Destroy(String id, String frame) implements Request {
        public Destroy {
            checkLimited(id, "id");
            requireNonNull(frame, "frame");
        }
    }

    /** Asks to hear of every change to frames of a class (and of the classes below it). */
    record Subscribe(String id, String ofClass) implements Request {
        public Subscribe {
            checkLimited(id, "id");
            checkLimited(ofClass, "ofClass");
        }
    }

    /** Stops a {@link Subscribe}. */
    record Unsubscribe(String id, String ofClass) implements Request {
        public Unsubscribe {
            checkLimited(id, "id");
            checkLimited(ofClass, "ofClass");
        }
    }

    /**
     * A change to a frame of a subscribed class; {@code frame} is the XML after the change, absent on removal. For a
     * sensor signal (an instance of {@code SensorSignal}) {@code values} carries its values typed as the {@code sensor}
     * message carried them: the XML's {@code values} list has no item type, so its items read back as text.
     */
    record Changed(String ofClass, ChangeKind change, String name, Optional<String> frame, Optional<List<Value>> values)
            implements Message {
        public Changed {
            requireNonNull(ofClass, "ofClass");
            requireNonNull(change, "change");
            requireNonNull(name, "name");
            requireNonNull(frame, "frame");
            values = requireNonNull(values, "values").map(List::copyOf);
        }

        /** A change of a frame that is not a sensor signal. */
        public Changed(String ofClass, ChangeKind change, String name, Optional<String> frame) {
            this(ofClass, change, name, frame, Optional.empty());
        }
    }

    /** Frames sent by another K-ICNP server, to be stored all or none. */
    record Push(String id, List<String> frames) implements Request {
        public Push {
            checkLimited(id, "id");
            frames = List.copyOf(frames);
        }
    }

    /** Asks another K-ICNP server for a subtree, or (without a root) its whole knowledge base. */
    record Pull(String id, Optional<String> root) implements Request {
        public Pull {
            checkLimited(id, "id");
            requireNonNull(root, "root");
        }
    }

    /**
     * Backward chaining: every instance of {@code ofClass} (or a class below it) that exists, or that behavior frames
     * could derive from what exists, whose instance slots hold the instances {@code bindings} names (slot → instance).
     * Nothing is created; a script condition runs on a binding of instances that exist (it cannot change anything).
     */
    record Prove(String id, String ofClass, Map<String, String> bindings) implements Request {
        public Prove {
            checkLimited(id, "id");
            checkLimited(ofClass, "ofClass");
            bindings = Map.copyOf(bindings);
        }
    }

    /** The answers to a {@code prove}, each with its proof. */
    record Proofs(String id, List<ProofNode> proofs) implements Message {
        public Proofs {
            requireNonNull(id, "id");
            proofs = List.copyOf(proofs);
        }
    }

    /**
     * One step of a proof: an instance that exists ({@code instance} present), or an instance the behavior frame
     * {@code ofClass} could create, with a proof for each of its required slots and the script conditions the proof
     * assumes: those of a binding that holds an instance still to be derived (a binding of existing instances has its
     * script conditions run).
     */
    record ProofNode(String ofClass, Optional<String> instance, Map<String, ProofNode> slots, List<String> assumptions) {
        public ProofNode {
            requireNonNull(ofClass, "ofClass");
            requireNonNull(instance, "instance");
            slots = ordered(slots);
            assumptions = List.copyOf(assumptions);
        }
    }

    /** Why an instance exists. */
    record Why(String id, String instance) implements Request {
        public Why {
            checkLimited(id, "id");
            requireNonNull(instance, "instance");
        }
    }

    /** The answer to a {@code why}. */
    record Explained(String id, Reason reason) implements Message {
        public Explained {
            requireNonNull(id, "id");
            requireNonNull(reason, "reason");
        }
    }

    /**
     * Why one instance exists: put in from outside (a stimulus, or knowledge loaded: {@code derived} false, nothing
     * else), or made by its behavior frame {@code ofClass} firing on {@code binding} (slot → instance), with each
     * slot condition as it was tested ({@code "slot: condition = value"}) and the reasons of the instances it rests
     * on, back to the stimuli.
     */
    record Reason(String instance, String ofClass, boolean derived, Map<String, String> binding,
                  List<String> conditions, List<Reason> supports) {
        public Reason {
            requireNonNull(instance, "instance");
            requireNonNull(ofClass, "ofClass");
            binding = ordered(binding);
            conditions = List.copyOf(conditions);
            supports = List.copyOf(supports);
        }
    }

    /**
     * Why the behavior frame {@code frame} has not fired, with the required slots {@code bindings} names held fixed
     * (slot → instance). Nothing is created on the server (script conditions run, as on matching, and cannot change
     * anything).
     */
    record WhyNot(String id, String frame, Map<String, String> bindings) implements Request {
        public WhyNot {
            checkLimited(id, "id");
            requireNonNull(frame, "frame");
            bindings = ordered(bindings);
        }
    }

    /**
     * The answer to a {@code why_not}: a one-sentence {@code summary}; each required slot with the instances that
     * could fill it and those its own condition turns away; then each binding of them (up to the server's answer
     * limit, {@code truncated} beyond) with its {@code outcome} and the reason.
     */
    record NotFired(String id, String frame, String summary, List<SlotCandidates> slots, List<BindingOutcome> bindings,
                    boolean truncated) implements Message {
        public NotFired {
            requireNonNull(id, "id");
            requireNonNull(frame, "frame");
            requireNonNull(summary, "summary");
            slots = List.copyOf(slots);
            bindings = List.copyOf(bindings);
        }
    }

    /**
     * A required slot of a {@code not_fired}: its class and condition, its candidates, and those turned away; each
     * list is cut at the server's answer limit, the counts say how many there are.
     */
    record SlotCandidates(String slot, String argument, String condition, List<String> candidates,
                          List<String> rejected, int candidateCount, int rejectedCount) {
        public SlotCandidates {
            requireNonNull(slot, "slot");
            requireNonNull(argument, "argument");
            requireNonNull(condition, "condition");
            candidates = List.copyOf(candidates);
            rejected = List.copyOf(rejected);
        }
    }

    /**
     * One binding of a {@code not_fired} (slot → instance) and what stops it: {@code condition_false},
     * {@code blocked}, {@code waiting}, {@code script_condition} or {@code would_fire}.
     */
    record BindingOutcome(Map<String, String> binding, String outcome, String reason) {
        public BindingOutcome {
            binding = ordered(binding);
            requireNonNull(outcome, "outcome");
            requireNonNull(reason, "reason");
        }
    }

    /** An error: the answer to the request {@code id} names, or (without an id) about the connection itself. */
    record ErrorReply(Optional<String> id, ErrorCode code, String message) implements Message {
        public ErrorReply {
            requireNonNull(id, "id");
            requireNonNull(code, "code");
            requireNonNull(message, "message");
        }

        /** An error answering one request. */
        public static ErrorReply to(String id, ErrorCode code, String message) {
            return new ErrorReply(Optional.of(id), code, message);
        }

        /** An error about the connection, answering no request. */
        public static ErrorReply of(ErrorCode code, String message) {
            return new ErrorReply(Optional.empty(), code, message);
        }
    }

    private static void checkLimited(String value, String member) {
        requireNonNull(value, member);
        checkLength(value, member);
    }

    private static void checkLength(String name, String member) {
        if (name.length() > MAX_NAME_LENGTH) {
            throw new IllegalArgumentException("The member '" + member + "' is " + name.length()
                    + " characters long; at most " + MAX_NAME_LENGTH + " are allowed.");
        }
    }

    /** An unmodifiable copy that keeps the given order (a frame's slot order), which {@link Map#copyOf} does not. */
    private static <V> Map<String, V> ordered(Map<String, V> map) {
        Map<String, V> copy = new java.util.LinkedHashMap<>(map.size() * 2);
        map.forEach((k, v) -> copy.put(requireNonNull(k, "key"), requireNonNull(v, "value")));
        return java.util.Collections.unmodifiableMap(copy);
    }

    private static void checkName(String name, String what) {
        requireNonNull(name, what);
        checkLength(name, what);
        if (!NAME.matcher(name).matches()) {
            throw new IllegalArgumentException("'" + name + "' is not a valid " + what
                    + " name: use letters, digits, '_' and '-', starting with a letter or '_'.");
        }
    }
}
