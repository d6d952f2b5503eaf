package org.kicnp.inference;

import java.util.List;
import java.util.Map;

/** Why an answer of backward chaining holds: it exists, or a behavior frame could derive it from sub-proofs. */
public sealed interface Proof {

    /** The class of the instance proved. */
    String className();

    /** An instance that exists in the knowledge base. */
    record Exists(String instance, String className) implements Proof { }

    /**
     * An instance {@code frame} would create, with a proof for each required slot. A script condition is run when
     * every instance of the binding exists (a binding it rejects is no proof); one whose binding holds an instance that
     * would itself be derived cannot be run before that instance exists, and is listed as an {@code assumption}
     * ("slot: js: ...").
     */
    record Derivable(String frame, Map<String, Proof> slots, List<String> assumptions) implements Proof {
        public Derivable {
            slots = Map.copyOf(slots);
            assumptions = List.copyOf(assumptions);
        }

        @Override public String className() {
            return frame;
        }
    }

    /** How deep the proof goes: 0 for an existing instance. */
    default int depth() {
        return switch (this) {
            case Exists e -> 0;
            case Derivable d -> 1 + d.slots().values().stream().mapToInt(Proof::depth).max().orElse(0);
        };
    }
}
