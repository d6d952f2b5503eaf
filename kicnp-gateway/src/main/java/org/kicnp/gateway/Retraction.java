package org.kicnp.gateway;

import org.kicnp.core.KnowledgeBase;

/**
 * How the gateway takes away a runtime frame (presence, sensor signal) of an agent that left. Plain removal fails
 * while a derived instance still refers to the frame, so a platform with an inference engine retracts through the
 * engine instead: the frame and everything derived from it go together (truth maintenance). Called on a gateway I/O
 * thread: return quickly (hand the work to the engine's thread).
 */
@FunctionalInterface
public interface Retraction {
    /** Takes the frame away; an unchecked exception is logged by the caller, naming the frame and the agent. */
    void retract(String frame);

    /** Plain removal from the knowledge base, for a gateway with no inference engine. */
    static Retraction removeFrom(KnowledgeBase kb) {
        return kb::remove;
    }
}
