package org.kicnp.gateway;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import org.kicnp.core.BatchRejectedException;
import org.kicnp.core.Change;
import org.kicnp.core.ChangeSet;
import org.kicnp.core.Frame;
import org.kicnp.core.FrameEvent;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.KnowledgeException;
import org.kicnp.core.KnowledgeListener;
import org.kicnp.core.Provenance;
import org.kicnp.core.UnknownFrameException;
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
    private final Set<Session> subscribers = ConcurrentHashMap.newKeySet();

    KnowledgeAccess(KnowledgeBase kb, Outbound out) {
        this.kb = kb;
        this.out = out;
    }

    Message query(Message.Query q) {
        if (!kb.contains(q.ofClass())) {
            return unknown(q.id(), q.ofClass());
        }
        return new Message.Frames(q.id(), FrameText.toXml(kb.instancesOf(q.ofClass())));
    }

    Message ask(Message.Ask a) {
        if (!kb.contains(a.frame())) {
            return unknown(a.id(), a.frame());
        }
        return new Message.Answer(a.id(), kb.value(a.frame(), a.slot()));
    }

    Message assertFrame(Session from, Message.Assert a) {
        List<Frame> frames;
        try {
            frames = FrameText.parse(a.frame(), "assert from " + from, kb);
        } catch (KnowledgeException | IllegalArgumentException e) {
            return ErrorReply.to(a.id(), ErrorCode.REJECTED, e.getMessage());
        }
        if (frames.size() != 1 || !frames.getFirst().isInstance()) {
            return ErrorReply.to(a.id(), ErrorCode.REJECTED, "An assert carries exactly one instance frame, not "
                    + frames.size() + " frame(s)" + (frames.size() == 1 ? " of kind class" : "") + ".");
        }
        Frame f = frames.getFirst().toBuilder().provenance(Provenance.RUNTIME).build();
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
        return apply(a.id(), List.of(new Change.Put(f)));
    }

    Message destroy(Message.Destroy d) {
        Optional<Frame> f = kb.frame(d.frame());
        if (f.isEmpty()) {
            return unknown(d.id(), d.frame());
        }
        if (!f.get().isInstance()) {
            return ErrorReply.to(d.id(), ErrorCode.FORBIDDEN,
                    "Frame '" + d.frame() + "' is a class; agents may destroy instances only.");
        }
        // The same rule as assert: declared (XML, editor) and learned instances are durable knowledge, and removing
        // one would erase it from the store for good, so only runtime instances may be destroyed.
        if (f.get().provenance().durable()) {
            return ErrorReply.to(d.id(), ErrorCode.FORBIDDEN, "Frame '" + d.frame() + "' is "
                    + f.get().provenance().name().toLowerCase(java.util.Locale.ROOT)
                    + " knowledge; agents may destroy runtime instances only.");
        }
        return apply(d.id(), List.of(new Change.Remove(d.frame())));
    }

    Message subscribe(Session s, Message.Subscribe sub) {
        if (!kb.contains(sub.ofClass())) {
            return unknown(sub.id(), sub.ofClass());
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
        try {
            for (int i = 0; i < p.frames().size(); i++) {
                for (Frame f : FrameText.parse(p.frames().get(i), "push from " + from + " #" + (i + 1), kb)) {
                    changes.add(new Change.Put(f));
                }
            }
        } catch (KnowledgeException | IllegalArgumentException e) {
            return ErrorReply.to(p.id(), ErrorCode.REJECTED, e.getMessage());
        }
        return apply(p.id(), changes);
    }

    /** A subtree (the root and every frame below it) or the whole knowledge base, parents first, no RUNTIME frames. */
    Message pull(Message.Pull p) {
        if (p.root().isPresent() && !kb.contains(p.root().get())) {
            return unknown(p.id(), p.root().get());
        }
        return new Message.Frames(p.id(), FrameText.toXml(Subtree.of(kb, p.root())));
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
                for (Session s : subscribers) {
                    for (String c : s.subscriptions()) {
                        if (classes.contains(c)) {
                            out.send(s, notification(c, e));
                        }
                    }
                }
            }
        } catch (RuntimeException e) { // never let a notification problem reach the knowledge base's committer
            LOG.error("Could not notify subscribers of change set {}.", changes.version(), e);
        }
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

    private static Message.Changed notification(String ofClass, FrameEvent e) {
        return switch (e) {
            case FrameEvent.Added a -> new Message.Changed(ofClass, ChangeKind.ADDED, a.name(),
                    Optional.of(FrameText.toXml(a.frame())));
            case FrameEvent.Replaced r -> new Message.Changed(ofClass, ChangeKind.REPLACED, r.name(),
                    Optional.of(FrameText.toXml(r.frame())));
            case FrameEvent.Removed r -> new Message.Changed(ofClass, ChangeKind.REMOVED, r.name(), Optional.empty());
        };
    }

    private Message apply(String id, List<Change> changes) {
        try {
            kb.apply(changes);
            return new Message.Ack(id);
        } catch (BatchRejectedException e) {
            StringBuilder sb = new StringBuilder("The knowledge base refused the change:");
            e.problems().forEach(pr -> sb.append(' ').append(pr));
            return ErrorReply.to(id, ErrorCode.REJECTED, sb.toString());
        } catch (UnknownFrameException e) {
            return ErrorReply.to(id, ErrorCode.UNKNOWN_FRAME, e.getMessage());
        } catch (KnowledgeException e) {
            return ErrorReply.to(id, ErrorCode.REJECTED, e.getMessage());
        }
    }

    private static ErrorReply unknown(String id, String frame) {
        return ErrorReply.to(id, ErrorCode.UNKNOWN_FRAME, "There is no frame named '" + frame + "'.");
    }
}
