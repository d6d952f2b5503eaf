package org.kicnp.inference;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/** The answer to "why does this instance exist?": a tree back to asserted instances (the stimuli). */
public sealed interface Explanation {
    String instance();

    /** An instance put into the knowledge base from outside: a stimulus, or knowledge loaded. */
    record Asserted(String instance, String className) implements Explanation { }

    /** An instance derived by a firing, with the explanations of what it rests on. */
    record Derived(Derivation derivation, List<Explanation> supports) implements Explanation {
        public Derived {
            supports = List.copyOf(supports);
        }

        @Override public String instance() {
            return derivation.instance();
        }
    }

    /** The stimuli this explanation rests on, in order, without repeats. */
    default List<String> stimuli() {
        LinkedHashSet<String> out = new LinkedHashSet<>();
        collect(this, out);
        return List.copyOf(out);
    }

    private static void collect(Explanation e, Set<String> out) {
        switch (e) {
            case Asserted a -> out.add(a.instance());
            case Derived d -> d.supports().forEach(s -> collect(s, out));
        }
    }
}
