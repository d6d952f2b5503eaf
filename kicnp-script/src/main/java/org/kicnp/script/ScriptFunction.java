package org.kicnp.script;

import java.util.List;

/**
 * A Java function a script can call, such as the paper's {@code Sendmsg(target, text)}. Arguments arrive as
 * plain Java values (see {@link ScriptValues#toJava}); the result is handed to the script with
 * {@link ScriptValues#toGuest}. Throwing fails the script with a {@link ScriptFailedException} whose cause is
 * the thrown exception.
 */
@FunctionalInterface
public interface ScriptFunction {

    /** Called with the script's arguments; returns what the script sees, or {@link Undefined#INSTANCE}. */
    Object call(List<Object> arguments);
}
