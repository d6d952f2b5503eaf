package org.kicnp.inference;

import java.util.List;
import java.util.Map;
import org.kicnp.core.Frame;
import org.kicnp.core.Value;

/**
 * What a script asked the engine to do. Effects are collected while the script runs and applied only when it
 * succeeds, so a script that throws or times out changes nothing.
 */
sealed interface Effect {
    record Create(String name, String className, Map<String, Value> slots) implements Effect { }

    record Destroy(String name) implements Effect { }

    record Issue(String id, String robot, String action, List<String> args) implements Effect { }

    record Learn(Frame frame) implements Effect { }

    /** Cancels an action by its id, or every unfinished action of a robot when {@code target} names a robot. */
    record Cancel(String target, String reason) implements Effect { }
}
