package org.kicnp.inference;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;

/**
 * Why a derived instance exists: the behavior frame that made it, the binding (slot → instance), each condition with
 * the value it was tested on, the firing number, the fact whose arrival completed the binding ({@code trigger}), and,
 * for an instance a script created, the instance whose firing ran that script. The binding is immutable and keeps
 * the order it was given in (the behavior frame's slot order for a firing).
 *
 * <p>A value class with the accessors, equality and text of a record of those seven components. Every derived
 * instance keeps one for as long as it lives, and few are ever read: so it holds the binding as its slots and
 * instances by position, and of the conditions only the values read along their paths (a condition with no path is
 * tested on the bound instance's name, which the binding holds), one object where a binding map and a list of
 * conditions were two more; {@link #binding()} and {@link #conditions()} are views made when asked.
 */
public final class Derivation {
    private final String instance;
    /**
     * The behavior frame and the instances bound, by position: the refraction key of the binding ({@link BindingKey}),
     * the one the firing's activation had, so a firing keeps one object for both.
     */
    private final BindingKey key;
    /** The binding's slots and, by position, the instances bound to them (never changed once made). */
    private final List<String> slots;
    /**
     * The conditions: with {@link #patterns}, what a firing kept of the values it tested, those of the patterns whose
     * condition reads a path ({@link CheckedConditions#kept}: null, the one value or an array; a
     * {@link CheckedConditions} when asked); with no patterns (null), the list itself.
     */
    private final List<SlotPattern> patterns;
    private final Object checked;
    private final long firing;
    private final String trigger;
    private final Optional<String> createdBy;

    public Derivation(String instance, String frame, Map<String, String> binding, List<CheckedCondition> conditions,
                      long firing, String trigger, Optional<String> createdBy) {
        Binding b = Binding.copyOf(binding);
        this.instance = requireNonNull(instance, "instance");
        this.key = new BindingKey(requireNonNull(frame, "frame"), b.factArray());
        this.slots = b.slotList();
        this.patterns = null;
        // A firing's own list is immutable already, and copying it would make every record it defers at once.
        this.checked = conditions instanceof CheckedConditions ? conditions : List.copyOf(conditions);
        this.firing = firing;
        this.trigger = requireNonNull(trigger, "trigger");
        this.createdBy = requireNonNull(createdBy, "createdBy");
    }

    /**
     * A firing's derivation: the rule's required slots bound to the instances of {@code key}, the refraction key of
     * the firing's activation (its instances never to be changed afterwards), and the conditions of {@code patterns}
     * tested on the values {@code tested} keeps ({@link CheckedConditions#kept}); no copies.
     */
    Derivation(String instance, BindingKey key, List<String> slots, List<SlotPattern> patterns, Object tested,
               long firing, String trigger) {
        this.instance = instance;
        this.key = key;
        this.slots = slots;
        this.patterns = patterns;
        this.checked = tested;
        this.firing = firing;
        this.trigger = trigger;
        this.createdBy = Optional.empty();
    }

    public String instance() {
        return instance;
    }

    public String frame() {
        return key.frame();
    }

    /** The binding, slot → instance, in slot order (immutable). */
    public Map<String, String> binding() {
        return Binding.wrap(slots, key.facts());
    }

    /** Each bound slot's condition and the value it was tested on (immutable). */
    @SuppressWarnings("unchecked")
    public List<CheckedCondition> conditions() {
        return patterns == null ? (List<CheckedCondition>) checked
                : new CheckedConditions(patterns, null, CheckedConditions.expand(patterns, key.facts(), checked));
    }

    public long firing() {
        return firing;
    }

    public String trigger() {
        return trigger;
    }

    public Optional<String> createdBy() {
        return createdBy;
    }

    /** The number of bound slots. */
    int width() {
        return key.width();
    }

    /** The instance bound to the slot at {@code position}. */
    String factAt(int position) {
        return key.fact(position);
    }

    /** The instances this one rests on: its binding, and the creating instance for a scripted creation. */
    List<String> supports() {
        String[] facts = key.facts();
        List<String> out = new ArrayList<>(facts.length + 1);
        out.addAll(List.of(facts));
        createdBy.ifPresent(out::add);
        return out;
    }

    @Override public boolean equals(Object o) {
        return o instanceof Derivation d && d.firing == firing && d.instance.equals(instance)
                && d.frame().equals(frame())
                && d.binding().equals(binding()) && d.conditions().equals(conditions()) && d.trigger.equals(trigger)
                && d.createdBy.equals(createdBy);
    }

    @Override public int hashCode() {
        return Objects.hash(instance, frame(), binding(), conditions(), firing, trigger, createdBy);
    }

    @Override public String toString() {
        return "Derivation[instance=" + instance + ", frame=" + frame() + ", binding=" + binding() + ", conditions="
                + conditions() + ", firing=" + firing + ", trigger=" + trigger + ", createdBy=" + createdBy + "]";
    }

    /** A slot condition as it was tested when the frame fired. */
    public record CheckedCondition(String slot, String condition, String value) { }
}
