package org.kicnp.inference;

/**
 * The binding being built while a new fact is joined: the fact at each required slot of the rule, by position
 * ({@code null} while unbound), read as a map slot → instance by the condition evaluator ({@link SlotBinding}).
 * The map view is read-only; the matcher sets positions directly. Owned by the engine thread.
 */
final class JoinBinding extends SlotBinding {
    private final String[] slots;
    /** The facts bound, by position; null where unbound. */
    final FactView.Fact[] refs;

    JoinBinding(String[] slots) {
        this.slots = slots;
        this.refs = new FactView.Fact[slots.length];
    }

    /** Whether the fact is bound at some position already (an instance fills one slot of a binding). */
    boolean holds(FactView.Fact fact) {
        for (FactView.Fact f : refs) {
            if (f == fact) {
                return true;
            }
        }
        return false;
    }

    @Override int width() {
        return slots.length;
    }

    @Override String slotAt(int position) {
        return slots[position];
    }

    @Override String factAt(int position) {
        FactView.Fact f = refs[position];
        return f == null ? null : f.name;
    }
}
