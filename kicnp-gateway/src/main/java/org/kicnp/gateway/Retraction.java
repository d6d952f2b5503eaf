package org.kicnp.gateway;

import java.util.List;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import org.kicnp.core.Change;
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
    /**
     * Takes the frame away if it is still at {@code expectedRevision} ({@link Change#ANY_REVISION}: whatever it is
     * now); a frame changed since is left as it is (a sensor reading that expires must not take a newer reading of the
     * same sensor with it: {@link org.kicnp.core.StaleRevisionException} where the removal is refused at once). An
     * unchecked exception is logged by the caller, naming the frame and the agent.
     */
    void retract(String frame, long expectedRevision);

    /** Takes the frame away, whatever its revision. */
    default void retract(String frame) {
        retract(frame, Change.ANY_REVISION);
    }

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
        return (frame, revision) -> kb.apply(List.of(new Change.Remove(frame, revision)));
    }
}
