package org.kicnp.bench;

import java.time.Duration;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.HdrHistogram.Histogram;
import org.kicnp.agent.AgentBase;
import org.kicnp.agent.AgentOptions;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.gateway.AgentDirectory;
import org.kicnp.gateway.FeedbackListener;
import org.kicnp.gateway.GatewayConfig;
import org.kicnp.gateway.GatewayServer;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Message;

/**
 * Ping-pong through the K-ICNP gateway on loopback: a user agent relays a body to a robot agent, which relays it
 * back. Each relay is acknowledged by the hub, so one round trip is two acknowledged sends and two deliveries —
 * the same shape as two QoS 1 publishes through an MQTT broker.
 */
final class KicnpPingPong {
    private static final Duration WAIT = Duration.ofSeconds(10);

    private KicnpPingPong() {
    }

    static PingPongResult run(int roundTrips, int warmup, int payloadBytes) throws InterruptedException {
        AgentDirectory agents = AgentDirectory.empty().with("echo", "echo-token", AgentKind.ROBOT)
                .with("pinger", "pinger-token", AgentKind.USER);
        try (GatewayServer gateway = GatewayServer.start(GatewayConfig.defaults().withPort(0), agents,
                KnowledgeBase.create(), FeedbackListener.NONE);
             Echo echo = new Echo(AgentOptions.of("127.0.0.1", gateway.port(), "echo", AgentKind.ROBOT, "echo-token"));
             Pinger pinger = new Pinger(AgentOptions.of("127.0.0.1", gateway.port(), "pinger", AgentKind.USER,
                     "pinger-token"))) {
            echo.startAndAwait(WAIT);
            pinger.startAndAwait(WAIT);
            String body = "x".repeat(payloadBytes);
            for (int i = 0; i < warmup; i++) {
                pinger.ping(body);
            }
            Histogram h = new Histogram(3);
            long start = System.nanoTime();
            for (int i = 0; i < roundTrips; i++) {
                long t0 = System.nanoTime();
                pinger.ping(body);
                h.recordValue(Math.max(1, (System.nanoTime() - t0) / 1_000));
            }
            return PingPongResult.of("K-ICNP gateway", payloadBytes, h, System.nanoTime() - start);
        }
    }

    private static final class Echo extends AgentBase {
        Echo(AgentOptions options) {
            super(options);
        }

        @Override protected void onRelay(Message.Relay relay) {
            relayTo(relay.from(), "pong", relay.body());
        }
    }

    private static final class Pinger extends AgentBase {
        private final BlockingQueue<String> pongs = new LinkedBlockingQueue<>();

        Pinger(AgentOptions options) {
            super(options);
        }

        @Override protected void onRelay(Message.Relay relay) {
            pongs.add(relay.body());
        }

        void ping(String body) throws InterruptedException {
            relayTo("echo", "ping", body);
            if (pongs.poll(WAIT.toMillis(), TimeUnit.MILLISECONDS) == null) {
                throw new IllegalStateException("No pong from 'echo' within " + WAIT + ".");
            }
        }
    }
}
