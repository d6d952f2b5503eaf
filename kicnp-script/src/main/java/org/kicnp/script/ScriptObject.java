package org.kicnp.script;

import java.util.Optional;
import java.util.Set;

/**
 * An object whose members are read when a script asks for them, not before: scripts see it as a read-only object,
 * and each member is read and converted (with {@link ScriptValues#toGuest}) the first time it is used in a run. Use it
 * for views onto large or linked data, such as a frame whose slots refer to other frames, where copying everything
 * up front would cost more than the script ever reads. Host functions given the object back receive it unchanged.
 */
public interface ScriptObject {
    /** The member's value as plain Java (or another {@code ScriptObject}), or empty when there is no such member. */
    Optional<Object> member(String key);

    /** Every member name, for scripts that enumerate the object ({@code Object.keys}, {@code for ... in}). */
    Set<String> memberKeys();
}
