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
     * A firing's rule patterns ({@code List<SlotPattern>}), or the creating instance of a scripted creation (a
     * {@code String}), or null: one field for the two, which no derivation has both of, so that the depth fits in the
     * 48 bytes a derivation took without it.
     */
    private final Object shape;
    /**
     * The conditions: with a firing's patterns ({@link #shape}), what the firing kept of the values it tested, those
     * of the patterns whose condition reads a path ({@link CheckedConditions#kept}: null, the one value or an array; a
     * {@link CheckedConditions} when asked); otherwise the list itself.
     */
    private final Object checked;
    private final long firing;
    private final String trigger;
    /** How many derived instances deep it rests: 1 + the deepest of what it rests on (an asserted instance: 0). */
    private final int depth;

    /** A derivation resting on asserted instances only (depth 1). */
    public Derivation(String instance, String frame, Map<String, String> binding, List<CheckedCondition> conditions,
                      long firing, String trigger, Optional<String> createdBy) {
        this(instance, frame, binding, conditions, firing, trigger, createdBy, 1);
    }

    /** @param depth 1 + the deepest {@link #depth} of the instances it rests on (0 for an asserted one) */
    public Derivation(String instance, String frame, Map<String, String> binding, List<CheckedCondition> conditions,
                      long firing, String trigger, Optional<String> createdBy, int depth) {
        Binding b = Binding.copyOf(binding);
        this.instance = requireNonNull(instance, "instance");
        this.key = new BindingKey(requireNonNull(frame, "frame"), b.factArray());
        this.slots = b.slotList();
        this.shape = requireNonNull(createdBy, "createdBy").orElse(null);
        // A firing's own list is immutable already, and copying it would make every record it defers at once.
        this.checked = conditions instanceof CheckedConditions ? conditions : List.copyOf(conditions);
        this.firing = firing;
        this.trigger = requireNonNull(trigger, "trigger");
        if (depth < 1) {
            throw new IllegalArgumentException("A derived instance rests at least 1 deep, not " + depth + ".");
        }
        this.depth = depth;
    }

    /**
     * A firing's derivation: the rule's required slots bound to the instances of {@code key}, the refraction key of
     * the firing's activation (its instances never to be changed afterwards), and the conditions of {@code patterns}
     * tested on the values {@code tested} keeps ({@link CheckedConditions#kept}); no copies.
     */
    Derivation(String instance, BindingKey key, List<String> slots, List<SlotPattern> patterns, Object tested,
               long firing, String trigger, int depth) {
        this.instance = instance;
        this.key = key;
        this.slots = slots;
        this.shape = patterns;
        this.checked = tested;
        this.firing = firing;
        this.trigger = trigger;
        this.depth = depth;
    }

    /**
     * The depth of an instance made from {@code refs}: one more than the deepest of them, an instance the engine did
     * not derive counting 0.
     */
    static int depthOver(FactView.Fact[] refs) {
        int deepest = 0;
        for (FactView.Fact f : refs) {
            if (f.derivation != null && f.derivation.depth > deepest) {
                deepest = f.derivation.depth;
            }
        }
        return deepest + 1;
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
        return shape instanceof List<?> patterns
                ? new CheckedConditions((List<SlotPattern>) patterns, null,
                        CheckedConditions.expand((List<SlotPattern>) patterns, key.facts(), checked))
                : (List<CheckedCondition>) checked;
    }

    public long firing() {
        return firing;
    }

    public String trigger() {
        return trigger;
    }

    public Optional<String> createdBy() {
        return shape instanceof String s ? Optional.of(s) : Optional.empty();
    }

    /**
     * How many derived instances deep it rests: 1 when it rests on asserted instances only, else one more than the
     * deepest derived instance it rests on. A knowledge base that feeds itself makes ever deeper instances.
     */
    public int depth() {
        return depth;
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
        createdBy().ifPresent(out::add);
        return out;
    }

    @Override public boolean equals(Object o) {
        return o instanceof Derivation d && d.firing == firing && d.instance.equals(instance)
                && d.frame().equals(frame())
                && d.binding().equals(binding()) && d.conditions().equals(conditions()) && d.trigger.equals(trigger)
                && d.createdBy().equals(createdBy());
    }

    @Override public int hashCode() {
        return Objects.hash(instance, frame(), binding(), conditions(), firing, trigger, createdBy());
    }

    @Override public String toString() {
        return "Derivation[instance=" + instance + ", frame=" + frame() + ", binding=" + binding() + ", conditions="
                + conditions() + ", firing=" + firing + ", trigger=" + trigger + ", createdBy=" + createdBy() + "]";
    }

    /** A slot condition as it was tested when the frame fired. */
    public record CheckedCondition(String slot, String condition, String value) { }
}
