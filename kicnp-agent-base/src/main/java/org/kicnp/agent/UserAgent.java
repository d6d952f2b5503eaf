package org.kicnp.agent;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.kicnp.protocol.Message;

/**
 * A ready-made user agent: relays a user's commands to robots ({@link #command}), queries their states, and keeps
 * what it hears (relays and change notifications) for the caller to read. Subclass it to react instead.
 */
public class UserAgent extends AgentBase {
    private final List<Message.Relay> relays = new CopyOnWriteArrayList<>();
    private final List<Message.Changed> changes = new CopyOnWriteArrayList<>();

    public UserAgent(AgentOptions options) {
        super(options);
    }

    @Override protected void onRelay(Message.Relay relay) {
        relays.add(relay);
    }

    @Override protected void onChanged(Message.Changed change) {
        changes.add(change);
    }

    /** The relays received so far, in order. */
    public List<Message.Relay> relays() {
        return List.copyOf(relays);
    }

    /** The change notifications received so far, in order. */
    public List<Message.Changed> changes() {
        return List.copyOf(changes);
    }
}
