package org.kicnp.gateway;

import static java.util.Objects.requireNonNull;

import io.netty.handler.ssl.SslContext;
import java.time.Duration;
import java.time.InstantSource;
import java.util.Optional;
import org.kicnp.protocol.Framing;

/**
 * How a gateway listens and what it bounds. Defaults: loopback only, port {@value #DEFAULT_PORT}, 1 MiB frames, 30 s heartbeat
 * timeout, 64/256 KiB write-buffer water marks, a slow consumer dropped after 1,000 consecutive shed messages,
 * no TLS, one I/O thread per core, the best socket transport available here ({@link Transport#best()}), the system's
 * clock. Immutable; the {@code with…} methods return changed copies.
 *
 * @param port 0 picks an ephemeral port (tests)
 * @param ioThreads the event loops serving connections (see {@link #withIoThreads})
 * @param transport the socket transport under those loops (see {@link Transport})
 * @param clock the wall clock of the times the server stamps (a presence's {@code since}, a sensor signal's
 *     {@code time} and {@code expires}, heartbeats, the {@code time} of a {@code frames} answer); never used to time
 *     anything, which runs on the JVM's monotonic clock (see {@link #withClock})
 */
public record GatewayConfig(String host, int port, String serverName, int maxFrameBytes, Duration heartbeatTimeout,
                            int writeLowWaterBytes, int writeHighWaterBytes, int maxShedBeforeDrop,
                            Optional<SslContext> tls, int ioThreads, Transport transport, InstantSource clock) {
    public GatewayConfig {
        requireNonNull(host, "host");
        requireNonNull(serverName, "serverName");
        requireNonNull(heartbeatTimeout, "heartbeatTimeout");
        requireNonNull(tls, "tls");
        requireNonNull(transport, "transport");
        requireNonNull(clock, "clock");
        if (port < 0 || port > 65_535) {
            throw new IllegalArgumentException("Port " + port + " is not between 0 and 65535.");
        }
        if (maxFrameBytes < 1024) {
            throw new IllegalArgumentException("A maximum frame of " + maxFrameBytes + " bytes is below 1024.");
        }
        if (writeLowWaterBytes <= 0 || writeHighWaterBytes < writeLowWaterBytes) {
            throw new IllegalArgumentException("Write-buffer water marks " + writeLowWaterBytes + "/"
                    + writeHighWaterBytes + " need 0 < low <= high.");
        }
        if (heartbeatTimeout.toMillis() < 30) {
            throw new IllegalArgumentException("A heartbeat timeout of " + heartbeatTimeout + " is too short.");
        }
        if (ioThreads < 1) {
            throw new IllegalArgumentException("A gateway needs at least 1 I/O thread, not " + ioThreads + ".");
        }
        if (maxShedBeforeDrop < 1) {
            throw new IllegalArgumentException("maxShedBeforeDrop must be at least 1, not " + maxShedBeforeDrop + ".");
        }
    }

    /** The port agents connect to unless configured otherwise; {@code kicnp serve} listens there too. */
    public static final int DEFAULT_PORT = 7777;

    /** The defaults: {@code 127.0.0.1:}{@value #DEFAULT_PORT}. */
    public static GatewayConfig defaults() {
        return new GatewayConfig("127.0.0.1", DEFAULT_PORT, "kicnp", Framing.DEFAULT_MAX_FRAME_BYTES, Duration.ofSeconds(30),
                64 * 1024, 256 * 1024, 1_000, Optional.empty(), Runtime.getRuntime().availableProcessors(),
                Transport.best(), InstantSource.system());
    }

    public GatewayConfig withHost(String h) {
        return new GatewayConfig(h, port, serverName, maxFrameBytes, heartbeatTimeout, writeLowWaterBytes,
                writeHighWaterBytes, maxShedBeforeDrop, tls, ioThreads, transport, clock);
    }

    public GatewayConfig withPort(int p) {
        return new GatewayConfig(host, p, serverName, maxFrameBytes, heartbeatTimeout, writeLowWaterBytes,
                writeHighWaterBytes, maxShedBeforeDrop, tls, ioThreads, transport, clock);
    }

    public GatewayConfig withServerName(String name) {
        return new GatewayConfig(host, port, name, maxFrameBytes, heartbeatTimeout, writeLowWaterBytes,
                writeHighWaterBytes, maxShedBeforeDrop, tls, ioThreads, transport, clock);
    }

    public GatewayConfig withMaxFrameBytes(int bytes) {
        return new GatewayConfig(host, port, serverName, bytes, heartbeatTimeout, writeLowWaterBytes,
                writeHighWaterBytes, maxShedBeforeDrop, tls, ioThreads, transport, clock);
    }

    public GatewayConfig withHeartbeatTimeout(Duration timeout) {
        return new GatewayConfig(host, port, serverName, maxFrameBytes, timeout, writeLowWaterBytes,
                writeHighWaterBytes, maxShedBeforeDrop, tls, ioThreads, transport, clock);
    }

    public GatewayConfig withWriteBuffer(int lowBytes, int highBytes, int maxShed) {
        return new GatewayConfig(host, port, serverName, maxFrameBytes, heartbeatTimeout, lowBytes, highBytes,
                maxShed, tls, ioThreads, transport, clock);
    }

    /**
     * The number of event loops serving connections. The default, one per core, keeps every core busy without
     * more threads than cores taking turns on them (Netty's own default is two per core).
     */
    public GatewayConfig withIoThreads(int threads) {
        return new GatewayConfig(host, port, serverName, maxFrameBytes, heartbeatTimeout, writeLowWaterBytes,
                writeHighWaterBytes, maxShedBeforeDrop, tls, threads, transport, clock);
    }

    /** The socket transport; one that does not work here makes {@link GatewayServer#start} fail, saying why. */
    public GatewayConfig withTransport(Transport t) {
        return new GatewayConfig(host, port, serverName, maxFrameBytes, heartbeatTimeout, writeLowWaterBytes,
                writeHighWaterBytes, maxShedBeforeDrop, tls, ioThreads, t, clock);
    }

    public GatewayConfig withTls(SslContext context) {
        return withTls(Optional.of(context));
    }

    /** With TLS on {@code context}, or plain TCP when it is empty. */
    public GatewayConfig withTls(Optional<SslContext> context) {
        return new GatewayConfig(host, port, serverName, maxFrameBytes, heartbeatTimeout, writeLowWaterBytes,
                writeHighWaterBytes, maxShedBeforeDrop, requireNonNull(context, "context"), ioThreads, transport,
                clock);
    }

    /**
     * With the wall clock of the times the server stamps: a test's clock set apart from an agent's, as on two machines
     * whose clocks disagree. What the server times (heartbeat timeouts, a signal's expiry) still runs on the JVM's
     * monotonic clock, so a clock that jumps cannot fire them early or late.
     */
    public GatewayConfig withClock(InstantSource c) {
        return new GatewayConfig(host, port, serverName, maxFrameBytes, heartbeatTimeout, writeLowWaterBytes,
                writeHighWaterBytes, maxShedBeforeDrop, tls, ioThreads, transport, requireNonNull(c, "clock"));
    }
}
