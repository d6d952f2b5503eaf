package org.kicnp.agent;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import javax.net.SocketFactory;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Framing;

/**
 * How an agent connects: where, as whom, and its timing. Defaults: 10 s request timeout, heartbeat every 5 s,
 * server silence tolerated for 40 s, reconnect backoff from 100 ms doubling to 5 s with jitter, 1 MiB frames,
 * plain TCP (pass an {@code SSLSocketFactory} for TLS). Immutable.
 */
public record AgentOptions(String host, int port, String name, AgentKind kind, String token, Duration requestTimeout,
                           Duration heartbeatInterval, Duration serverSilence, Duration backoffInitial,
                           Duration backoffMax, int maxFrameBytes, SocketFactory socketFactory) {
    public AgentOptions {
        requireNonNull(host, "host");
        requireNonNull(name, "name");
        requireNonNull(kind, "kind");
        requireNonNull(token, "token");
        requireNonNull(requestTimeout, "requestTimeout");
        requireNonNull(heartbeatInterval, "heartbeatInterval");
        requireNonNull(serverSilence, "serverSilence");
        requireNonNull(backoffInitial, "backoffInitial");
        requireNonNull(backoffMax, "backoffMax");
        requireNonNull(socketFactory, "socketFactory");
    }

    /** Options with the defaults for an agent at {@code host:port}. */
    public static AgentOptions of(String host, int port, String name, AgentKind kind, String token) {
        return new AgentOptions(host, port, name, kind, token, Duration.ofSeconds(10), Duration.ofSeconds(5),
                Duration.ofSeconds(40), Duration.ofMillis(100), Duration.ofSeconds(5), Framing.DEFAULT_MAX_FRAME_BYTES,
                SocketFactory.getDefault());
    }

    public AgentOptions withPort(int p) {
        return new AgentOptions(host, p, name, kind, token, requestTimeout, heartbeatInterval, serverSilence,
                backoffInitial, backoffMax, maxFrameBytes, socketFactory);
    }

    public AgentOptions withToken(String t) {
        return new AgentOptions(host, port, name, kind, t, requestTimeout, heartbeatInterval, serverSilence,
                backoffInitial, backoffMax, maxFrameBytes, socketFactory);
    }

    public AgentOptions withBackoff(Duration initial, Duration max) {
        return new AgentOptions(host, port, name, kind, token, requestTimeout, heartbeatInterval, serverSilence,
                initial, max, maxFrameBytes, socketFactory);
    }

    /** How long a request (query, assert, prove, …) waits for its answer. */
    public AgentOptions withRequestTimeout(Duration timeout) {
        return new AgentOptions(host, port, name, kind, token, timeout, heartbeatInterval, serverSilence,
                backoffInitial, backoffMax, maxFrameBytes, socketFactory);
    }

    /**
     * How often the agent sends a heartbeat when it has sent nothing else, and how long it tolerates hearing nothing
     * from the server before it takes the connection for lost and reconnects: keep the silence above the server's
     * heartbeat timeout's third (the server's heartbeat interval) with room to spare.
     */
    public AgentOptions withHeartbeat(Duration interval, Duration silence) {
        return new AgentOptions(host, port, name, kind, token, requestTimeout, interval, silence, backoffInitial,
                backoffMax, maxFrameBytes, socketFactory);
    }

    /** The largest frame the agent sends or accepts, in bytes (the server's limit is 1 MiB by default). */
    public AgentOptions withMaxFrameBytes(int bytes) {
        return new AgentOptions(host, port, name, kind, token, requestTimeout, heartbeatInterval, serverSilence,
                backoffInitial, backoffMax, bytes, socketFactory);
    }

    public AgentOptions withSocketFactory(SocketFactory factory) {
        return new AgentOptions(host, port, name, kind, token, requestTimeout, heartbeatInterval, serverSilence,
                backoffInitial, backoffMax, maxFrameBytes, factory);
    }
}
