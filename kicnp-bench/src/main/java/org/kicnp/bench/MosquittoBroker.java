package org.kicnp.bench;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import java.util.concurrent.TimeUnit;

/**
 * A Mosquitto broker on loopback for the length of a benchmark, started and stopped by
 * {@code scripts/mosquitto.sh} (which installs Debian's package when it is missing, unless told not to).
 */
final class MosquittoBroker implements AutoCloseable {
    private final Path script;
    private final Path dir;
    private final InetSocketAddress address;
    /** The broker's process id (0: unknown), read from its pid file at the start, before any client runs. */
    private final long pid;

    private MosquittoBroker(Path script, Path dir, InetSocketAddress address) {
        this.script = script;
        this.dir = dir;
        this.address = address;
        this.pid = readPid(dir);
    }

    /**
     * Starts a broker through the script.
     *
     * @param install whether the script may install Mosquitto with apt-get
     * @throws IllegalStateException when the script fails; its message quotes the script's own words
     */
    static MosquittoBroker start(Path script, boolean install) throws IOException, InterruptedException {
        Path dir = Files.createTempDirectory("kicnp-mosquitto");
        ProcessBuilder pb = new ProcessBuilder("bash", script.toString(), "start", dir.toString());
        if (!install) {
            pb.environment().put("KICNP_NO_INSTALL", "1");
        }
        Process p = pb.redirectErrorStream(false).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
        String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8).strip();
        if (!p.waitFor(10, TimeUnit.MINUTES) || p.exitValue() != 0 || !out.startsWith("port=")) {
            throw new IllegalStateException("'" + script + " start' failed (exit " + (p.isAlive() ? "none" : p.exitValue())
                    + "): " + (err.isEmpty() ? out : err));
        }
        int port = Integer.parseInt(out.lines().reduce((a, b) -> b).orElseThrow().substring("port=".length()));
        return new MosquittoBroker(script, dir, new InetSocketAddress("127.0.0.1", port));
    }

    /** The script beside this build: {@code scripts/mosquitto.sh} of the source tree the classes were built in. */
    static Optional<Path> defaultScript() {
        try {
            Path code = Path.of(MosquittoBroker.class.getProtectionDomain().getCodeSource().getLocation().toURI());
            // kicnp-bench/target/kicnp-bench.jar or kicnp-bench/target/classes: the tree is three levels up.
            for (Path p = code; p != null; p = p.getParent()) {
                Path candidate = p.resolve("scripts").resolve("mosquitto.sh");
                if (Files.isRegularFile(candidate)) {
                    return Optional.of(candidate);
                }
            }
        } catch (URISyntaxException | SecurityException e) {
            return Optional.empty();
        }
        return Optional.empty();
    }

    /** Whether a Mosquitto executable is installed, on the PATH or in Debian's {@code /usr/sbin}. */
    static boolean installed() {
        return MosquittoPingPong.executable().isPresent();
    }

    InetSocketAddress address() {
        return address;
    }

    /** The broker's version line, e.g. {@code mosquitto version 2.0.11}; empty if it cannot be read. */
    static String version() {
        return MosquittoPingPong.executable().map(exe -> {
            try {
                Process p = new ProcessBuilder(exe.toString(), "-h").redirectErrorStream(true).start();
                String first = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).lines()
                        .findFirst().orElse("");
                p.waitFor(5, TimeUnit.SECONDS);
                return first.strip();
            } catch (IOException e) {
                return "";
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return "";
            }
        }).orElse("");
    }

    /** The broker's process id from the script's pid file; 0 if unreadable. */
    private static long readPid(Path dir) {
        try {
            return Long.parseLong(Files.readString(dir.resolve("mosquitto.pid")).strip());
        } catch (IOException | RuntimeException e) {
            return 0;
        }
    }

    /** The broker's CPU time so far (user and system), in nanoseconds, from {@code /proc}; 0 if unknown. */
    long cpuNanos() {
        return pid == 0 ? 0 : ProcessCpu.nanos(pid);
    }

    @Override public void close() throws IOException, InterruptedException {
        Process p = new ProcessBuilder("bash", script.toString(), "stop", dir.toString())
                .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        p.waitFor(30, TimeUnit.SECONDS);
    }
}
