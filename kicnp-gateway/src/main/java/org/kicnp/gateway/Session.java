package org.kicnp.gateway;

import static java.util.Objects.requireNonNull;

import io.netty.channel.Channel;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;
import org.kicnp.protocol.AgentKind;

/**
 * One agent connection as the server agent sees it: who it is once authenticated, whether it registered, what it
 * subscribed to, and how many messages to it were shed in a row. State changes happen on the channel's event loop.
 */
final class Session {
    enum State { NEW, AUTHENTICATED, REGISTERED, CLOSING }

    private final Channel channel;
    private volatile State state = State.NEW;
    private volatile String agent = "";
    private volatile AgentKind kind = AgentKind.SERVICE;
    private volatile List<String> capabilities = List.of();
    private final Set<String> subscriptions = ConcurrentHashMap.newKeySet();
    final AtomicInteger shedInARow = new AtomicInteger();
    /** Commands sent to this (robot) connection and not yet ended or failed. */
    final AtomicInteger commandsInFlight = new AtomicInteger();

    Session(Channel channel) {
        this.channel = requireNonNull(channel, "channel");
    }

    Channel channel() {
        return channel;
    }

    State state() {
        return state;
    }

    void authenticated(String name, AgentKind k) {
        this.agent = name;
        this.kind = k;
        this.state = State.AUTHENTICATED;
    }

    void registered(List<String> capabilityNames) {
        this.capabilities = List.copyOf(capabilityNames);
        this.state = State.REGISTERED;
    }

    void closing() {
        this.state = State.CLOSING;
    }

    /** The authenticated agent name; empty before authentication. */
    String agent() {
        return agent;
    }

    AgentKind kind() {
        return kind;
    }

    List<String> capabilities() {
        return capabilities;
    }

    Set<String> subscriptions() {
        return subscriptions;
    }

    @Override public String toString() {
        return agent.isEmpty() ? String.valueOf(channel.remoteAddress()) : "'" + agent + "'";
    }
}
