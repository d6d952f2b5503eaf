package org.kicnp.gateway;

import java.time.InstantSource;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ConcurrentHashMap;
import java.util.stream.Collectors;
import org.kicnp.core.BatchRejectedException;
import org.kicnp.core.Change;
import org.kicnp.core.ChangeSet;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.FrameEvent;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.KnowledgeException;
import org.kicnp.core.KnowledgeListener;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.UnknownFrameException;
import org.kicnp.core.Value;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.ChangeKind;
import org.kicnp.protocol.ErrorCode;
import org.kicnp.protocol.FrameText;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.Message.ErrorReply;

/**
 * The knowledge side of the gateway: query, ask, assert, destroy, subscriptions with change notifications, and
 * knowledge between platforms (push taken all-or-none, pull of a subtree or everything). Each request method
 * returns the answer to send. Thread-safe; the knowledge base does the locking.
 */
final class KnowledgeAccess implements KnowledgeListener {
    private static final org.slf4j.Logger LOG = org.slf4j.LoggerFactory.getLogger(KnowledgeAccess.class);
    private final KnowledgeBase kb;
    private final Outbound out;
    private final Retraction retraction;
    private final Reasoning reasoning;
    /** The wall clock of a {@code frames} answer's time ({@link GatewayConfig#clock}). */
    private final InstantSource clock;
    private final Set<Session> subscribers = ConcurrentHashMap.newKeySet();

    KnowledgeAccess(KnowledgeBase kb, Outbound out, Retraction retraction, Reasoning reasoning,
            InstantSource clock) {
        this.kb = kb;
        this.out = out;
        this.retraction = retraction;
        this.reasoning = reasoning;
        this.clock = clock;
    }

    Message query(Message.Query q) {
        Optional<Frame> c = kb.frame(q.ofClass());
        if (c.isEmpty()) {
            return unknown(q.id(), q.ofClass());
        }
        if (c.get().isInstance()) {
            return notAClass(q.id(), q.ofClass(), "query");
        }
        long now = clock.millis(); // the clock RuntimeFrames stamps a signal's time and expires with
        return new Message.Frames(q.id(), FrameText.toXml(kb.instancesOf(q.ofClass()).stream()
                .map(this::selfDescribed).toList()), Optional.of(now));
    }

    /** A slot's effective value; an empty answer means the slot has no value, a slot no frame declares is refused. */
    Message ask(Message.Ask a) {
        if (!kb.contains(a.frame())) {
            return unknown(a.id(), a.frame());
        }
        if (kb.slot(a.frame(), a.slot()).isEmpty()) {
            return ErrorReply.to(a.id(), ErrorCode.REJECTED, "Frame '" + a.frame() + "' has no slot '" + a.slot()
                    + "', of its own or inherited.");
        }
        return new Message.Answer(a.id(), kb.value(a.frame(), a.slot()));
    }

    /** Query and subscribe take a class: an instance has no instances, so they would answer nothing, for good. */
    private static ErrorReply notAClass(String id, String frame, String what) {
        return ErrorReply.to(id, ErrorCode.REJECTED, "Frame '" + frame + "' is an instance; " + what
                + " takes a class (its instances and those of the classes below it).");
    }

    /**
     * One or more instance frames (several under one root element), stored as RUNTIME instances in one batch: all or
     * none.
     */
    Message assertFrame(Session from, Message.Assert a) {
        List<Frame> frames;
        try {
            frames = FrameText.parse(a.frame(), "assert from " + from, kb);
        } catch (KnowledgeException | IllegalArgumentException e) {
            return ErrorReply.to(a.id(), ErrorCode.REJECTED, e.getMessage());
        }
        if (frames.isEmpty()) {
            return ErrorReply.to(a.id(), ErrorCode.REJECTED, "An assert carries one or more instance frames, not none.");
        }
        List<Change> puts = new ArrayList<>(frames.size());
        for (Frame parsed : frames) {
            if (!parsed.isInstance()) {
                return ErrorReply.to(a.id(), ErrorCode.REJECTED, "An assert carries instance frames only; '"
                        + parsed.name() + "' is a class.");
            }
            Frame f = parsed.toBuilder().provenance(Provenance.RUNTIME).build();
            // An assert is a runtime fact: replacing a class or declared (or learned) knowledge with it would erase
            // that knowledge from the store for good, so only runtime instances may be replaced.
            Optional<Frame> existing = kb.frame(f.name());
            if (existing.isPresent() && !existing.get().isInstance()) {
                return ErrorReply.to(a.id(), ErrorCode.FORBIDDEN, "Frame '" + f.name()
                        + "' is a class; an assert may add or replace runtime instances only.");
            }
            if (existing.isPresent() && existing.get().provenance().durable()) {
                return ErrorReply.to(a.id(), ErrorCode.FORBIDDEN, "Frame '" + f.name() + "' is "
                        + existing.get().provenance().name().toLowerCase(java.util.Locale.ROOT)
                        + " knowledge; an assert may add or replace runtime instances only.");
            }
            puts.add(new Change.Put(f));
        }
        return apply(a.id(), puts);
    }

    /**
     * Destroys an instance through the {@link Retraction}, so that what was derived from it goes too (in the platform,
     * the inference engine's truth maintenance); the answer completes once it is done.
     */
    CompletableFuture<Message> destroy(Message.Destroy d) {
        Optional<Frame> f = kb.frame(d.frame());
        if (f.isEmpty()) {
            return CompletableFuture.completedFuture(unknown(d.id(), d.frame()));
        }
        if (!f.get().isInstance()) {
            return CompletableFuture.completedFuture(ErrorReply.to(d.id(), ErrorCode.FORBIDDEN,
                    "Frame '" + d.frame() + "' is a class; agents may destroy instances only."));
        }
        // The same rule as assert: declared (XML, editor) and learned instances are durable knowledge, and removing
        // one would erase it from the store for good, so only runtime instances may be destroyed.
        if (f.get().provenance().durable()) {
            return CompletableFuture.completedFuture(ErrorReply.to(d.id(), ErrorCode.FORBIDDEN, "Frame '" + d.frame()
                    + "' is " + f.get().provenance().name().toLowerCase(java.util.Locale.ROOT)
                    + " knowledge; agents may destroy runtime instances only."));
        }
        try {
            return retraction.destroy(d.frame()).handle((removed, failure) -> failure == null
                    ? new Message.Ack(d.id()) : refusal(d.id(), cause(failure)));
        } catch (RuntimeException e) { // a retraction that throws (an engine thread shut down): answer, keep the connection
            return CompletableFuture.completedFuture(refusal(d.id(), e));
        }
    }

    /** Backward chaining through the {@link Reasoning}: every answer with its proof, nothing created. */
    CompletableFuture<Message> prove(Message.Prove p) {
        Optional<Frame> c = kb.frame(p.ofClass());
        if (c.isEmpty()) {
            return CompletableFuture.completedFuture(unknown(p.id(), p.ofClass()));
        }
        if (c.get().isInstance()) {
            return CompletableFuture.completedFuture(ErrorReply.to(p.id(), ErrorCode.REJECTED, "Frame '"
                    + p.ofClass() + "' is an instance; prove takes a class."));
        }
        // A binding that names no instance, or a slot no answer could have, would only make the answer empty: say so.
        for (var b : p.bindings().entrySet()) {
            Optional<ErrorReply> refused = refusedBinding(p, b.getKey(), b.getValue());
            if (refused.isPresent()) {
                return CompletableFuture.completedFuture(refused.get());
            }
        }
        try {
            return reasoning.prove(p.ofClass(), p.bindings()).handle((proofs, failure) -> failure == null
                    ? new Message.Proofs(p.id(), proofs) : refusal(p.id(), cause(failure)));
        } catch (RuntimeException e) { // a Reasoning that throws rather than fail its future: answer, keep the connection
            return CompletableFuture.completedFuture(refusal(p.id(), e));
        }
    }

    /**
     * Why a prove's binding of {@code slot} to {@code instance} could only make the answer empty — no such instance,
     * a class, a slot no answer has, a slot that holds no instances, or none of the kind named — or empty if it may not.
     */
    private Optional<ErrorReply> refusedBinding(Message.Prove p, String slot, String instance) {
        Optional<Frame> bound = kb.frame(instance);
        if (bound.isEmpty()) {
            return Optional.of(ErrorReply.to(p.id(), ErrorCode.UNKNOWN_FRAME, "Binding '" + slot + "' names '" + instance
                    + "', but there is no frame of that name."));
        }
        if (!bound.get().isInstance()) {
            return Optional.of(ErrorReply.to(p.id(), ErrorCode.REJECTED, "Binding '" + slot + "' names '" + instance
                    + "', which is a class; a binding names an instance."));
        }
        List<Slot> slots = slotsAtOrBelow(p.ofClass(), slot);
        if (slots.isEmpty()) {
            return Optional.of(ErrorReply.to(p.id(), ErrorCode.REJECTED, "Neither class '" + p.ofClass()
                    + "' nor any class below it has a slot '" + slot + "' to bind."));
        }
        List<Slot> instanceSlots = slots.stream().filter(s -> s.type() == DataType.INSTANCE || s.type() == DataType.FRAME)
                .toList();
        if (instanceSlots.isEmpty()) {
            return Optional.of(ErrorReply.to(p.id(), ErrorCode.REJECTED, "Slot '" + slot + "' of class '" + p.ofClass()
                    + "' holds " + slots.stream().map(s -> s.type().xmlName()).distinct().sorted()
                    .collect(Collectors.joining(" or ")) + " values, not instances; a binding names an instance for an "
                    + "instance slot."));
        }
        if (instanceSlots.stream().noneMatch(s -> s.argument().map(a -> kb.isA(instance, a)).orElse(true))) {
            return Optional.of(ErrorReply.to(p.id(), ErrorCode.REJECTED, "Binding '" + slot + "' names '" + instance
                    + "', an instance of '" + bound.get().parent().orElse("") + "', but slot '" + slot + "' of class '"
                    + p.ofClass() + "' holds instances of " + instanceSlots.stream().flatMap(s -> s.argument().stream())
                    .distinct().sorted().map(a -> "'" + a + "'").collect(Collectors.joining(" or ")) + " only."));
        }
        return Optional.empty();
    }

    /** The slot as {@code cls}, and each class below it, has (or inherits) it; empty when none has it. */
    private List<Slot> slotsAtOrBelow(String cls, String slot) {
        java.util.ArrayDeque<String> todo = new java.util.ArrayDeque<>(List.of(cls));
        Set<String> seen = new HashSet<>();
        List<Slot> slots = new ArrayList<>();
        while (!todo.isEmpty()) {
            String f = todo.pop();
            if (!seen.add(f)) {
                continue;
            }
            kb.slot(f, slot).ifPresent(found -> slots.add(found.slot()));
            kb.children(f).stream().filter(ch -> !ch.isInstance()).forEach(ch -> todo.push(ch.name()));
        }
        return slots;
    }

    /** Why an instance exists, through the {@link Reasoning}. */
    CompletableFuture<Message> why(Message.Why w) {
        Optional<Frame> f = kb.frame(w.instance());
        if (f.isEmpty()) {
            return CompletableFuture.completedFuture(unknown(w.id(), w.instance()));
        }
        if (!f.get().isInstance()) {
            return CompletableFuture.completedFuture(ErrorReply.to(w.id(), ErrorCode.REJECTED, "Frame '"
                    + w.instance() + "' is a class; why explains instances only."));
        }
        try {
            return reasoning.why(w.instance()).handle((reason, failure) -> failure == null
                    ? new Message.Explained(w.id(), reason) : refusal(w.id(), cause(failure)));
        } catch (RuntimeException e) {
            return CompletableFuture.completedFuture(refusal(w.id(), e));
        }
    }

    /** Why a behavior frame has not fired, through the {@link Reasoning}. */
    CompletableFuture<Message> whyNot(Message.WhyNot w) {
        if (!kb.contains(w.frame())) {
            return CompletableFuture.completedFuture(unknown(w.id(), w.frame()));
        }
        try {
            return reasoning.whyNot(w.id(), w.frame(), w.bindings()).handle((answer, failure) -> failure == null
                    ? answer : refusal(w.id(), cause(failure)));
        } catch (RuntimeException e) {
            return CompletableFuture.completedFuture(refusal(w.id(), e));
        }
    }

    /** Whether an exception's message is a sentence for the agent (the platform's refusals are), not a JDK detail. */
    private static boolean isSentence(Throwable e) {
        return e.getMessage() != null && e.getMessage().endsWith(".");
    }

    private static Throwable cause(Throwable failure) {
        return failure instanceof CompletionException c && c.getCause() != null ? c.getCause() : failure;
    }

    Message subscribe(Session s, Message.Subscribe sub) {
        Optional<Frame> c = kb.frame(sub.ofClass());
        if (c.isEmpty()) {
            return unknown(sub.id(), sub.ofClass());
        }
        if (c.get().isInstance()) {
            return notAClass(sub.id(), sub.ofClass(), "subscribe");
        }
        s.subscriptions().add(sub.ofClass());
        subscribers.add(s);
        return new Message.Ack(sub.id());
    }

    Message unsubscribe(Session s, Message.Unsubscribe u) {
        s.subscriptions().remove(u.ofClass());
        return new Message.Ack(u.id());
    }

    /** Frames from another platform: parsed, then stored as one batch of upserts, all or none. */
    Message push(Session from, Message.Push p) {
        if (from.kind() != AgentKind.PEER) {
            return ErrorReply.to(p.id(), ErrorCode.FORBIDDEN, "Only peer servers may push frames; " + from
                    + " is a " + from.kind().name().toLowerCase(java.util.Locale.ROOT) + " agent.");
        }
        List<Change> changes = new ArrayList<>();
        List<String> live = new ArrayList<>();
        try {
            // One set, not text by text: an instance's list items take their type from its class in the same push.
            for (Frame f : FrameText.parse(p.frames(), i -> "push from " + from + " #" + (i + 1), kb)) {
                changes.add(new Change.Put(f));
                // This platform's live state (presences, sensor signals, what its engine derived) is its own.
                kb.frame(f.name()).filter(old -> old.isInstance() && old.provenance() == Provenance.RUNTIME)
                        .ifPresent(old -> live.add("'" + old.name() + "'"));
            }
        } catch (KnowledgeException | IllegalArgumentException e) {
            return ErrorReply.to(p.id(), ErrorCode.REJECTED, e.getMessage());
        }
        if (!live.isEmpty()) {
            return ErrorReply.to(p.id(), ErrorCode.FORBIDDEN, "The push from " + from + " would replace this "
                    + "platform's runtime instances " + String.join(", ", live) + " (presences, sensor signals, "
                    + "derived instances); nothing was stored.");
        }
        return apply(p.id(), changes);
    }

    /** A subtree (the root and every frame below it) or the whole knowledge base, parents first, no RUNTIME frames. */
    Message pull(Message.Pull p) {
        Optional<Frame> root = p.root().flatMap(kb::frame);
        if (p.root().isPresent() && root.isEmpty()) {
            return unknown(p.id(), p.root().get());
        }
        if (root.isPresent() && !root.get().provenance().durable()) {
            return ErrorReply.to(p.id(), ErrorCode.REJECTED, "'" + p.root().get() + "' exists only at run time on "
                    + "this platform; pull sends durable frames (declared and learned), so it has none to send.");
        }
        long now = clock.millis();
        return new Message.Frames(p.id(), FrameText.toXml(Subtree.of(kb, p.root())), Optional.of(now));
    }

    void connectionClosed(Session s) {
        subscribers.remove(s);
    }

    @Override public void changed(ChangeSet changes) {
        if (subscribers.isEmpty()) {
            return;
        }
        try {
            for (FrameEvent e : changes.events()) {
                Set<String> classes = classesOf(e.frame());
                Optional<String> xml = null; // the frame as agents read it: written once per event, when needed
                Optional<List<Value>> values = signalValues(e, classes);
                for (Session s : subscribers) {
                    for (String c : s.subscriptions()) {
                        if (classes.contains(c)) {
                            if (xml == null) {
                                xml = e instanceof FrameEvent.Removed ? Optional.empty()
                                        : Optional.of(FrameText.toXml(selfDescribed(e.frame())));
                            }
                            out.send(s, notification(c, e, xml, values));
                        }
                    }
                }
            }
        } catch (RuntimeException e) { // never let a notification problem reach the knowledge base's committer
            LOG.error("Could not notify subscribers of change set {}.", changes.version(), e);
        }
    }

    /**
     * An instance as an agent reads it alone: each list slot that takes its item type from a class above (its own
     * slot names no ARGUMENT) names it, so that the agent, which has no classes to read it against, gets the items
     * typed as they are (1.5, not "1.5"). The frame is otherwise as stored.
     */
    private Frame selfDescribed(Frame f) {
        if (!f.isInstance()) {
            return f;
        }
        Frame out = f;
        for (Slot own : f.slots()) {
            if (own.type() == DataType.LIST && own.argument().isEmpty()) {
                Optional<String> inherited = kb.slot(f.name(), own.name()).flatMap(e -> e.slot().argument());
                if (inherited.isPresent()) {
                    out = out.withSlot(own.toBuilder().argument(inherited.get()).build());
                }
            }
        }
        return out;
    }

    private Set<String> classesOf(Frame f) {
        Set<String> out = new HashSet<>();
        f.parent().ifPresent(p -> {
            out.add(p);
            if (kb.contains(p)) {
                out.addAll(kb.ancestors(p));
            }
        });
        return out;
    }

    /**
     * A sensor signal's values, typed: the XML of its {@code values} list has no item type (its items may be of any
     * type), so an agent reading the frame alone would get them as text.
     */
    private static Optional<List<Value>> signalValues(FrameEvent e, Set<String> classes) {
        if (e instanceof FrameEvent.Removed || !classes.contains(RuntimeFrames.SENSOR_SIGNAL)) {
            return Optional.empty();
        }
        return e.frame().ownSlot("values").flatMap(Slot::value)
                .map(v -> v instanceof Value.Lst l ? l.items() : List.of(v));
    }

    private static Message.Changed notification(String ofClass, FrameEvent e, Optional<String> xml,
                                                Optional<List<Value>> values) {
        ChangeKind kind = switch (e) {
            case FrameEvent.Added a -> ChangeKind.ADDED;
            case FrameEvent.Replaced r -> ChangeKind.REPLACED;
            case FrameEvent.Removed r -> ChangeKind.REMOVED;
        };
        return new Message.Changed(ofClass, kind, e.name(), xml, values);
    }

    private Message apply(String id, List<Change> changes) {
        try {
            kb.apply(changes);
            return new Message.Ack(id);
        } catch (KnowledgeException e) {
            return refusal(id, e);
        }
    }

    /** The error answering a request the knowledge base (or the engine) refused. */
    private static ErrorReply refusal(String id, Throwable e) {
        return switch (e) {
            case BatchRejectedException b -> {
                StringBuilder sb = new StringBuilder("The knowledge base refused the change:");
                b.problems().forEach(pr -> sb.append(' ').append(pr));
                yield ErrorReply.to(id, ErrorCode.REJECTED, sb.toString());
            }
            case UnknownFrameException u -> ErrorReply.to(id, ErrorCode.UNKNOWN_FRAME, u.getMessage());
            case KnowledgeException k -> ErrorReply.to(id, ErrorCode.REJECTED, k.getMessage());
            case IllegalStateException x when isSentence(x) -> ErrorReply.to(id, ErrorCode.REJECTED, x.getMessage());
            case IllegalArgumentException x when isSentence(x) -> ErrorReply.to(id, ErrorCode.REJECTED, x.getMessage());
            default -> {
                LOG.warn("A change failed unexpectedly: {}", e.toString());
                yield ErrorReply.to(id, ErrorCode.REJECTED, "The change failed: " + e.getMessage());
            }
        };
    }

    private static ErrorReply unknown(String id, String frame) {
        return ErrorReply.to(id, ErrorCode.UNKNOWN_FRAME, "There is no frame named '" + frame + "'.");
    }
}
