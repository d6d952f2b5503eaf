package org.kicnp.inference;

import java.util.Map;

/**
 * A complete binding of a behavior frame's required slots, waiting on the agenda to fire. {@code facts} are the bound
 * instances in the order of the rule's required slots; {@code recency} is the assertion stamp of the newest of them;
 * {@code seq} orders activations made at the same moment and tells activations apart.
 */
final class Activation {
    private final Rule rule;
    private final String[] facts;
    private final FactView.Fact[] refs;
    private final long recency;
    private final long seq;
    private final BindingKey key;
    private final long rank;
    /** Where the activation sits in the agenda's heap; -1 when it is not queued. */
    int heapIndex = -1;
    /** Whether the activation waits in a recency group of the agenda's {@link ActivationQueue}. */
    boolean stacked;
    /**
     * Set when a change that matches nothing again (a non-reactive slot's) reached one of its bound instances while it
     * waited: its conditions are checked again before it fires ({@link ForwardChainer#mayFire}).
     */
    boolean changed;

    Activation(Rule rule, String[] facts, FactView.Fact[] refs, long recency, long seq) {
        this(rule, facts, refs, recency, seq, new BindingKey(rule.frame(), facts));
    }

    /** As above, with the binding's key made already ({@code new BindingKey(rule.frame(), facts)}). */
    Activation(Rule rule, String[] facts, FactView.Fact[] refs, long recency, long seq, BindingKey key) {
        this.rule = rule;
        this.facts = facts;
        this.refs = refs;
        this.recency = recency;
        this.seq = seq;
        this.key = key;
        this.rank = Agenda.rank(rule);
    }

    /** The rule's place in the conflict-resolution order ({@link Agenda#rank}). */
    long rank() {
        return rank;
    }

    Rule rule() {
        return rule;
    }

    /** The bound instances, in the order of {@link Rule#required()}; not to be changed. */
    String[] facts() {
        return facts;
    }

    /** The engine's records of the bound instances, in the same order as {@link #facts()}; not to be changed. */
    FactView.Fact[] refs() {
        return refs;
    }

    long recency() {
        return recency;
    }

    long seq() {
        return seq;
    }

    /** The refraction key: the frame and its binding, in slot order. */
    BindingKey key() {
        return key;
    }

    /** The binding as slot → instance, in slot order (immutable; shares {@link #facts()}). */
    Binding binding() {
        return bindingOf(rule, facts);
    }

    /** The binding of a rule's required slots to {@code facts}, which must not be changed afterwards. */
    static Binding bindingOf(Rule rule, String[] facts) {
        return Binding.wrap(rule.requiredSlots(), facts);
    }

    /** The facts of a binding given as slot → instance, in the order of the rule's required slots. */
    static String[] factsOf(Rule rule, Map<String, String> binding) {
        String[] out = new String[rule.required().size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = binding.get(rule.required().get(i).slot());
        }
        return out;
    }

    /** Activations are told apart by their sequence number, which is unique per engine. */
    @Override public boolean equals(Object o) {
        return o instanceof Activation a && a.seq == seq;
    }

    @Override public int hashCode() {
        return Long.hashCode(seq);
    }

    @Override public String toString() {
        return "Activation" + key + "#" + seq;
    }
}
