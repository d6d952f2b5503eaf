package org.kicnp.inference;

import java.util.List;
import java.util.Map;

/** One step of inference, as a {@link TraceListener} sees it. A closed set. */
public sealed interface TraceEvent {

    /** A short kind name for printing: the record's simple name. */
    default String kind() {
        return getClass().getSimpleName();
    }

    /** An instance entered working memory (asserted from outside, or derived). */
    record FactAsserted(String instance, String className, long stamp) implements TraceEvent { }

    /** An instance's slots changed and it was matched again. */
    record FactChanged(String instance) implements TraceEvent { }

    /** An instance left working memory. */
    record FactRemoved(String instance) implements TraceEvent { }

    /** A complete binding of a behavior frame was found. */
    record Matched(String frame, Map<String, String> binding) implements TraceEvent { }

    /** A match was put on the agenda. */
    record Activated(String frame, Map<String, String> binding, int agendaSize) implements TraceEvent { }

    /** A binding was not activated or not fired: refracted, consumed, key taken or script condition false. */
    record Blocked(String frame, Map<String, String> binding, String reason) implements TraceEvent { }

    /** A behavior frame fired and created an instance. */
    record Fired(String frame, String instance, Map<String, String> binding, long firing) implements TraceEvent { }

    /** A script (slot of a frame) was run for an instance. */
    record ScriptCalled(String frame, String slot, String instance) implements TraceEvent { }

    /** A script failed or timed out; what it would have changed was discarded. */
    record ScriptFailed(String frame, String slot, String instance, String message) implements TraceEvent { }

    /** A derived instance was retracted, with the reason. */
    record Retracted(String instance, String reason) implements TraceEvent { }

    /** An action was issued by a firing. */
    record ActionIssued(Action action) implements TraceEvent { }

    /** An action changed state (held, sent, started, ended, failed, timed out). */
    record ActionChanged(String actionId, Action.Status status, String detail) implements TraceEvent { }

    /**
     * A limit stopped a run: the firings in a row ({@link EngineOptions#maxFirings}) or the depth of derived instances
     * ({@link EngineOptions#maxDerivationDepth}); {@code message} says which, as the exception the run ends with.
     */
    record LimitReached(int limit, List<String> topFrames, String message) implements TraceEvent { }
}
