package org.kicnp.inference;

import java.util.Comparator;
import java.util.List;

/**
 * The conflict set, in conflict-resolution order: explicit priority (higher first), then specificity (the deeper
 * frame in the hierarchy first, then the frame with more conditions), then recency (the binding whose newest fact
 * is newest first), then the order activations were made. Activations are withdrawn when a fact they bind leaves.
 */
final class Agenda {
    static final Comparator<Activation> ORDER = (a, b) -> {
        int c = Long.compare(b.rank(), a.rank());
        if (c == 0) {
            c = Long.compare(b.recency(), a.recency());
        }
        return c != 0 ? c : Long.compare(a.seq(), b.seq());
    };

    /**
     * The rule's part of the order in one number, higher first: priority, then depth, then number of conditions
     * (depth and conditions above 65,535 count as 65,535), so that ordering activations reads no rule.
     */
    static long rank(Rule r) {
        return ((long) r.priority() << 32) | ((long) Math.min(r.depth(), 0xFFFF) << 16)
                | Math.min(r.conditionCount(), 0xFFFF);
    }

    private final ActivationQueue queue = new ActivationQueue();
    /** Where each fact's activations are kept (its {@link FactView.Fact}), so a fact leaving withdraws them. */
    private final FactView facts;

    Agenda(FactView facts) {
        this.facts = facts;
    }

    /**
     * Whether a binding is waiting already, read from the activations of the bound fact that takes part in the
     * fewest. Only bindings matched again (after a claim was freed) can repeat one on the agenda; a new fact's
     * bindings are new, so the engine asks only then.
     */
    boolean contains(BindingKey key, FactView.Fact[] refs) {
        Object fewest = null;
        for (FactView.Fact f : refs) {
            if (f.activations == null) {
                return false;
            }
            if (fewest == null || Bag.size(f.activations) < Bag.size(fewest)) {
                fewest = f.activations;
            }
        }
        for (Activation a : Bag.<Activation>toList(fewest)) {
            if (a.key().equals(key)) {
                return true;
            }
        }
        return false;
    }

    /** Puts an activation on the agenda; the caller has made sure its binding is not waiting already. */
    void add(Activation a) {
        queue.add(a);
        for (FactView.Fact f : a.refs()) {
            f.activation(a);
        }
    }

    /** Takes the first activation off the agenda; null when it is empty (no Optional per firing). */
    Activation poll() {
        Activation a = queue.poll();
        if (a != null) {
            forget(a);
        }
        return a;
    }

    /** Withdraws every activation that binds the fact. */
    void withdrawFact(String fact) {
        FactView.Fact f = facts.get(fact);
        if (f != null && f.activations != null) {
            List<Activation> as = f.activations();
            f.activations = null;
            for (Activation a : as) {
                queue.remove(a);
                forget(a);
            }
        }
    }

    /** Withdraws every activation of the frame. */
    void withdrawRule(String frame) {
        for (Activation a : queue.snapshot()) {
            if (a.rule().frame().equals(frame)) {
                queue.remove(a);
                forget(a);
            }
        }
    }

    void clear() {
        queue.clear();
        for (FactView.Fact f : facts.all()) {
            f.activations = null;
        }
    }

    int size() {
        return queue.size();
    }

    /** The waiting activations in the order they would fire, copied. */
    List<Activation> inOrder() {
        return queue.inOrder();
    }

    private void forget(Activation a) {
        for (FactView.Fact f : a.refs()) {
            f.activations = Bag.remove(f.activations, a);
        }
    }
}
