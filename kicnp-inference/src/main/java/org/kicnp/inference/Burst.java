package org.kicnp.inference;

import java.util.Map;
import org.kicnp.core.KnowledgeBase;

/**
 * The engine thread's {@linkplain KnowledgeBase#hold hold} on the knowledge base across a run of firings: taken before
 * a firing, kept for the next ones so that each firing's commit and the engine's reads take no lock, and given back
 * after {@value #FIRINGS} firings, before any script runs (a script may take long, and may wait on other threads), and
 * when the run ends. Other threads wait at most that many firings to read or change the knowledge base. Used under
 * the engine's lock only.
 */
final class Burst {
    /** Firings per hold at most. */
    static final int FIRINGS = 64;

    private final KnowledgeBase kb;
    private KnowledgeBase.Hold hold;
    private int firings;

    Burst(KnowledgeBase kb) {
        this.kb = kb;
    }

    /** Before a firing: holds the knowledge base, unless held already. */
    void beforeFiring() {
        if (hold == null) {
            hold = kb.hold();
        }
    }

    /** After a firing: gives the hold back once it has lasted {@value #FIRINGS} firings. */
    void afterFiring() {
        if (hold != null && ++firings >= FIRINGS) {
            release();
        }
    }

    /** Gives the hold back, if held. */
    void release() {
        KnowledgeBase.Hold h = hold;
        if (h != null) {
            hold = null;
            firings = 0;
            h.close();
        }
    }

    /** Whether the knowledge base is held now (for tests). */
    boolean holding() {
        return hold != null;
    }

    /** {@code host}, giving the hold back before each script it runs. */
    ScriptHost releasingBefore(ScriptHost host) {
        return new ScriptHost() {
            @Override public Object run(String frame, String slot, String source, Map<String, Object> globals) {
                release();
                return host.run(frame, slot, source, globals);
            }

            @Override public boolean test(String frame, String slot, String source,
                    Map<String, Object> globals) {
                release();
                return host.test(frame, slot, source, globals);
            }

            @Override public void prepare(String frame, String slot, String source) {
                host.prepare(frame, slot, source); // on another thread, ahead of time: no knowledge base
            }
        };
    }
}
