package org.kicnp.bench;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.kicnp.gateway.Transport;

/**
 * The gateway in a JVM of its own ({@link GatewayMain}), started by the bench as Mosquitto is started by its script:
 * the same Java and class path as the bench, the JVM options the {@code ./kicnp} launcher gives {@code kicnp serve}
 * (Netty's access to {@code sun.nio.ch} and, from JDK 24 on, {@code sun.misc.Unsafe}), the JVM's default collector
 * and heap sizing, plus any options given. The clients' garbage collections, compilations and safepoints then no
 * longer stop the gateway, and its CPU time is its own process's, as Mosquitto's is.
 */
final class GatewayProcess implements KicnpHub {
    private final Process process;
    private final BufferedReader replies;
    private final Writer commands;
    private final InetSocketAddress address;
    private final List<String> javaOptions;

    private GatewayProcess(Process process, BufferedReader replies, Writer commands, InetSocketAddress address,
                           List<String> javaOptions) {
        this.process = process;
        this.replies = replies;
        this.commands = commands;
        this.address = address;
        this.javaOptions = javaOptions;
    }

    /**
     * Starts the gateway process and waits until it listens.
     *
     * @param agents the bench agents it authenticates ({@code a00000 ...})
     * @param ioThreads its I/O threads; 0 keeps the gateway's default (one per core)
     * @param transport its socket transport
     * @param extraOptions JVM options added after the launcher's (e.g. a collector)
     * @throws IllegalStateException when it does not come up; the message says how it ended
     */
    static GatewayProcess start(int agents, int ioThreads, Transport transport, List<String> extraOptions)
            throws IOException {
        List<String> options = new ArrayList<>(launcherOptions());
        options.add("-Dorg.slf4j.simpleLogger.log.org.kicnp.gateway=warn"); // not a line per connection
        options.addAll(extraOptions);
        List<String> command = new ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        command.addAll(options);
        command.addAll(List.of("-cp", System.getProperty("java.class.path"), GatewayMain.class.getName(),
                Integer.toString(agents), Integer.toString(ioThreads), transport.label()));
        Process p = new ProcessBuilder(command).redirectError(ProcessBuilder.Redirect.INHERIT).start();
        BufferedReader replies = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
        Writer commands = new OutputStreamWriter(p.getOutputStream(), StandardCharsets.UTF_8);
        String first = replyTo(replies, "port");
        if (first == null) {
            p.destroyForcibly();
            throw new IllegalStateException("The gateway process (" + GatewayMain.class.getName() + ") ended before "
                    + "it listened; see its messages above.");
        }
        int port = Integer.parseInt(first.substring("port=".length()));
        return new GatewayProcess(p, replies, commands, new InetSocketAddress("127.0.0.1", port), List.copyOf(options));
    }

    /**
     * The next line that answers {@code key} ({@code key=…}), skipping any other output (a JVM agent such as a
     * profiler may print on standard output too); null when the process's output ends first.
     */
    private static String replyTo(BufferedReader replies, String key) throws IOException {
        for (String line = replies.readLine(); line != null; line = replies.readLine()) {
            if (line.startsWith(key + "=")) {
                return line;
            }
        }
        return null;
    }

    /**
     * What {@code ./kicnp} passes every Java verb, {@code kicnp serve} included: Netty may reach into
     * {@code sun.nio.ch} (no garbage per ready key), load its native transports without the JDK's warning (from
     * JDK 22 on) and, from JDK 24 on, use {@code sun.misc.Unsafe}.
     */
    static List<String> launcherOptions() {
        List<String> o = new ArrayList<>(List.of("--add-opens=java.base/sun.nio.ch=ALL-UNNAMED",
                "-Dio.netty.tryReflectionSetAccessible=true"));
        if (Runtime.version().feature() >= 22) {
            o.add("--enable-native-access=ALL-UNNAMED");
        }
        if (Runtime.version().feature() >= 24) {
            o.add("--sun-misc-unsafe-memory-access=allow");
        }
        return o;
    }

    /** The process's id (for {@code /proc}). */
    long pid() {
        return process.pid();
    }

    boolean isAlive() {
        return process.isAlive();
    }

    @Override public InetSocketAddress address() {
        return address;
    }

    @Override public long shed() {
        return Long.parseLong(ask("shed"));
    }

    /** The gateway process's own CPU time; the clients run elsewhere. */
    @Override public long cpuNanos(long clientCpuNanos) {
        return ProcessCpu.nanos(process.pid());
    }

    @Override public String metrics() {
        return ask("metrics");
    }

    @Override public String describe() {
        return "its own JVM (pid " + process.pid() + ", " + String.join(" ", javaOptions) + ")";
    }

    private synchronized String ask(String command) {
        try {
            commands.write(command + "\n");
            commands.flush();
            String reply = replyTo(replies, command);
            if (reply == null) {
                throw new IllegalStateException("The gateway process ended without answering '" + command + "'.");
            }
            return reply.substring(command.length() + 1);
        } catch (IOException e) {
            throw new IllegalStateException("The gateway process did not answer '" + command + "': " + e.getMessage(), e);
        }
    }

    /** Ends its standard input, which stops it; waits up to 10 s, then kills it. */
    @Override public void close() {
        try {
            commands.close();
        } catch (IOException e) {
            // it has gone already
        }
        try {
            if (!process.waitFor(10, TimeUnit.SECONDS)) {
                process.destroyForcibly().waitFor(5, TimeUnit.SECONDS);
            }
        } catch (InterruptedException e) {
            process.destroyForcibly();
            Thread.currentThread().interrupt();
        }
    }
}
