package org.kicnp.gateway;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import org.kicnp.protocol.AgentKind;

/** The registered agents by name: where the hub routes relays and commands. Thread-safe. */
final class AgentRegistry {
    private final Map<String, Session> byName = new ConcurrentHashMap<>();

    /** Registers a session, returning the older session of the same name that it replaces, if any. */
    Optional<Session> register(Session s) {
        Session old = byName.put(s.agent(), s);
        return old == s ? Optional.empty() : Optional.ofNullable(old);
    }

    /** Removes the session if it is still the registered one for its name; says whether it was. */
    boolean unregister(Session s) {
        return byName.remove(s.agent(), s);
    }

    Optional<Session> find(String agent) {
        return Optional.ofNullable(sessionOf(agent));
    }

    /** As {@link #find}, null when no agent of that name is registered: the relay path's look-up, with no garbage. */
    Session sessionOf(String agent) {
        return byName.get(agent);
    }

    List<Session> ofKind(AgentKind kind) {
        return byName.values().stream().filter(s -> s.kind() == kind).toList();
    }

    List<Session> all() {
        return List.copyOf(byName.values());
    }

    List<String> names() {
        return byName.keySet().stream().sorted().toList();
    }
}
