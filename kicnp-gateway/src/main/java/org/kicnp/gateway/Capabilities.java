package org.kicnp.gateway;

import java.util.List;
import java.util.Optional;
import org.kicnp.core.DataType;
import org.kicnp.core.EffectiveSlot;
import org.kicnp.core.Frame;

/**
 * What an agent's {@code register} may replace. Registering again with changed capability frames replaces the old
 * ones (a robot tells the platform what it can do each time it connects), but a capability frame must not overwrite
 * the knowledge base's own frames under the same name: an instance, a behavior frame (a class with a required
 * instance slot, its own or inherited: the engine's rules), or a class placed elsewhere in the hierarchy. Any authenticated agent can
 * register, so without this a robot could strip a behavior frame of its slots or move a class.
 */
final class Capabilities {
    private Capabilities() {
    }

    /**
     * Why {@code incoming} may not replace {@code existing} (a sentence), or empty when it may; {@code slots} are
     * {@code existing}'s effective slots (inherited ones included).
     */
    static Optional<String> whyNotReplaceable(Frame existing, List<EffectiveSlot> slots, Frame incoming) {
        String name = "'" + existing.name() + "'";
        if (existing.isInstance()) {
            return Optional.of("Frame " + name + " is an instance of the knowledge base; a capability may not replace"
                    + " it.");
        }
        boolean behavior = slots.stream().map(EffectiveSlot::slot)
                .anyMatch(sl -> sl.required() && sl.type() == DataType.INSTANCE);
        if (behavior) {
            return Optional.of("Frame " + name + " is a behavior frame of the knowledge base; a capability may not"
                    + " replace it.");
        }
        if (!existing.parent().equals(incoming.parent())) {
            return Optional.of("Frame " + name + " is " + existing.parent().map(p -> "below '" + p + "'")
                    .orElse("a root class") + "; a capability of that name " + incoming.parent().map(
                    p -> "below '" + p + "'").orElse("as a root class") + " would move it.");
        }
        return Optional.empty();
    }
}
