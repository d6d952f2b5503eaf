package org.kicnp.inference;

import java.util.List;

/** A function the engine offers scripts ({@code sendmsg}, {@code create}, ...); arguments arrive as plain Java. */
@FunctionalInterface
public interface HostFunction {
    Object call(List<Object> args);
}
