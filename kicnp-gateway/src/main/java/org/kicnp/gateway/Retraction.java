package org.kicnp.gateway;

import java.util.Set;
import java.util.concurrent.CompletableFuture;
import org.kicnp.core.KnowledgeBase;

/**
 * How the gateway takes away a runtime frame (presence, sensor signal) of an agent that left, and an instance an agent
 * destroys. Plain removal fails
 * while a derived instance still refers to the frame, so a platform with an inference engine retracts through the
 * engine instead: the frame and everything derived from it go together (truth maintenance). Called on a gateway I/O
 * thread: return quickly (hand the work to the engine's thread).
 */
@FunctionalInterface
public interface Retraction {
    /** Takes the frame away; an unchecked exception is logged by the caller, naming the frame and the agent. */
    void retract(String frame);

    /**
     * Destroys an instance an agent asked to destroy, with what rests on it; completes with the names removed, or
     * exceptionally with the reason it could not be (such as the knowledge base's refusal). Called on a gateway I/O
     * thread: return at once and complete later where the work is long. By default {@link #retract} on the calling
     * thread, for a retraction that removes at once (as {@link #removeFrom} does).
     */
    default CompletableFuture<Set<String>> destroy(String frame) {
        try {
            retract(frame);
            return CompletableFuture.completedFuture(Set.of(frame));
        } catch (RuntimeException e) {
            return CompletableFuture.failedFuture(e);
        }
    }

    /** Plain removal from the knowledge base, for a gateway with no inference engine. */
    static Retraction removeFrom(KnowledgeBase kb) {
        return kb::remove;
    }
}
