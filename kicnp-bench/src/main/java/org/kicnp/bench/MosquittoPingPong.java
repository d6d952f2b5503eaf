package org.kicnp.bench;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.HdrHistogram.Histogram;
import org.eclipse.paho.client.mqttv3.MqttClient;
import org.eclipse.paho.client.mqttv3.MqttConnectOptions;
import org.eclipse.paho.client.mqttv3.MqttException;
import org.eclipse.paho.client.mqttv3.persist.MemoryPersistence;

/**
 * The same ping-pong through a Mosquitto broker on loopback with Paho clients: the pinger publishes to
 * {@code kicnp/ping} with QoS 1, the echo client publishes what it gets to {@code kicnp/pong} with QoS 1. Mosquitto
 * is started as a child process on a free port; when it is not installed the result says so.
 */
final class MosquittoPingPong {
    static final String PEER = "Mosquitto (MQTT QoS 1)";

    private MosquittoPingPong() {
    }

    /** The Mosquitto executable, from the PATH or Debian's {@code /usr/sbin}. */
    static Optional<Path> executable() {
        Stream<Path> dirs = Stream.concat(
                Stream.of(System.getenv().getOrDefault("PATH", "").split(java.io.File.pathSeparator)).map(Path::of),
                Stream.of(Path.of("/usr/sbin"), Path.of("/usr/local/sbin")));
        return dirs.map(d -> d.resolve("mosquitto")).filter(Files::isExecutable).findFirst();
    }

    static PingPongResult run(int roundTrips, int warmup, int payloadBytes) throws Exception {
        Optional<Path> exe = executable();
        if (exe.isEmpty()) {
            return PingPongResult.skipped(PEER, payloadBytes, "Mosquitto is not installed (apt-get install mosquitto).");
        }
        int port = freePort();
        // Nagle's algorithm off on both sides, as K-ICNP's gateway and SDK do; otherwise MQTT pays ~40 ms a hop.
        Path conf = Files.createTempFile("kicnp-mosquitto", ".conf");
        Files.writeString(conf, "listener " + port + " 127.0.0.1\nallow_anonymous true\nset_tcp_nodelay true\n");
        Process broker = new ProcessBuilder(exe.get().toString(), "-c", conf.toString())
                .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        try {
            awaitListening(port, broker);
            String url = "tcp://127.0.0.1:" + port;
            MqttClient echo = connect(url, "kicnp-echo");
            MqttClient pinger = connect(url, "kicnp-pinger");
            try {
                echo.subscribe("kicnp/ping", 1, (topic, msg) -> echo.publish("kicnp/pong", msg.getPayload(), 1, false));
                BlockingQueue<byte[]> pongs = new LinkedBlockingQueue<>();
                pinger.subscribe("kicnp/pong", 1, (topic, msg) -> pongs.add(msg.getPayload()));
                byte[] body = "x".repeat(payloadBytes).getBytes(StandardCharsets.UTF_8);
                for (int i = 0; i < warmup; i++) {
                    ping(pinger, pongs, body);
                }
                Histogram h = new Histogram(3);
                long start = System.nanoTime();
                for (int i = 0; i < roundTrips; i++) {
                    long t0 = System.nanoTime();
                    ping(pinger, pongs, body);
                    h.recordValue(Math.max(1, (System.nanoTime() - t0) / 1_000));
                }
                return PingPongResult.of(PEER, payloadBytes, h, System.nanoTime() - start);
            } finally {
                pinger.disconnect();
                echo.disconnect();
                pinger.close();
                echo.close();
            }
        } finally {
            broker.destroy();
            broker.waitFor(5, TimeUnit.SECONDS);
            Files.deleteIfExists(conf);
        }
    }

    private static void ping(MqttClient pinger, BlockingQueue<byte[]> pongs, byte[] body) throws Exception {
        pinger.publish("kicnp/ping", body, 1, false); // returns once the broker acknowledged it (PUBACK)
        if (pongs.poll(10, TimeUnit.SECONDS) == null) {
            throw new IllegalStateException("No pong through Mosquitto within 10 s.");
        }
    }

    private static MqttClient connect(String url, String id) throws MqttException {
        MqttClient c = new MqttClient(url, id, new MemoryPersistence());
        MqttConnectOptions o = new MqttConnectOptions();
        o.setCleanSession(true);
        o.setAutomaticReconnect(false);
        o.setSocketFactory(new NoDelaySocketFactory());
        c.connect(o);
        return c;
    }

    /** Plain sockets with TCP_NODELAY, which Paho does not set by itself. */
    private static final class NoDelaySocketFactory extends javax.net.SocketFactory {
        private final javax.net.SocketFactory plain = javax.net.SocketFactory.getDefault();

        @Override public Socket createSocket() throws IOException {
            Socket s = plain.createSocket();
            s.setTcpNoDelay(true);
            return s;
        }

        @Override public Socket createSocket(String host, int port) throws IOException {
            Socket s = plain.createSocket(host, port);
            s.setTcpNoDelay(true);
            return s;
        }

        @Override public Socket createSocket(String host, int port, InetAddress local, int localPort) throws IOException {
            Socket s = plain.createSocket(host, port, local, localPort);
            s.setTcpNoDelay(true);
            return s;
        }

        @Override public Socket createSocket(InetAddress host, int port) throws IOException {
            Socket s = plain.createSocket(host, port);
            s.setTcpNoDelay(true);
            return s;
        }

        @Override public Socket createSocket(InetAddress address, int port, InetAddress local, int localPort)
                throws IOException {
            Socket s = plain.createSocket(address, port, local, localPort);
            s.setTcpNoDelay(true);
            return s;
        }
    }

    private static int freePort() throws IOException {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        }
    }

    private static void awaitListening(int port, Process broker) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (System.nanoTime() < deadline) {
            if (!broker.isAlive()) {
                throw new IllegalStateException("Mosquitto exited with " + broker.exitValue() + " before listening on "
                        + port + ".");
            }
            try (Socket s = new Socket(InetAddress.getLoopbackAddress(), port)) {
                return;
            } catch (IOException notYet) {
                Thread.sleep(20);
            }
        }
        throw new IllegalStateException("Mosquitto did not listen on port " + port + " within 10 s.");
    }
}
