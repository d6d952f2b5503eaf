package org.kicnp.robots;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;

/**
 * The simulator's operating-system process and its three pipes, for a {@link SimWorld}: request lines go to stdin
 * through a queue and one writer thread (so a simulator that reads nothing blocks no caller), each stdout line goes to
 * the world from one reader thread, stderr is followed by a {@link SimStderr}, and when a pipe ends the reason is
 * worked out (an exit code, a signal, the simulator's last words, a broken pipe) and handed to the world once.
 *
 * <p>Kept apart from {@link SimWorld}, which speaks the protocol over these lines (ids, acks, actions, events,
 * timeouts) and knows nothing of processes, pipes or exit codes.
 */
final class SimProcess {
    /** The world's logger, so that logging set up for the simulator still covers these lines. */
    private static final Logger LOG = LoggerFactory.getLogger(SimWorld.class);

    private final Process process;
    private final Writer stdin;
    private final SimStderr stderr = new SimStderr();
    /** Lines for the simulator's stdin, written by one thread, so that a simulator that reads nothing blocks no caller. */
    private final BlockingQueue<String> outbox = new LinkedBlockingQueue<>();
    private Thread reader;

    private SimProcess(Process process) {
        this.process = process;
        this.stdin = new OutputStreamWriter(process.getOutputStream(), StandardCharsets.UTF_8);
    }

    /** Starts {@code python -m kicnp_sim} of the repository's simulator with the options' seed, time scale and mode. */
    static SimProcess launch(SimOptions options) {
        SimInstallation sim = SimInstallation.locate(options.repoRoot());
        List<String> cmd = new ArrayList<>(List.of(sim.python().toString(), "-m", "kicnp_sim",
                "--seed", Long.toString(options.seed()), "--time-scale", Double.toString(options.timeScale())));
        if (options.manual()) {
            cmd.add("--manual");
        }
        try {
            return new SimProcess(new ProcessBuilder(cmd).directory(sim.simDir().toFile()).start());
        } catch (IOException e) {
            throw new SimulatorException("Could not start the simulator '" + String.join(" ", cmd) + "': "
                    + e.getMessage(), e);
        }
    }

    /**
     * Starts following the pipes: stderr first (a quick death's reason quotes it), then stdout, each line to
     * {@code lines}, and stdin, written while {@code alive} holds. When stdout ends or stdin breaks, {@code ended}
     * gets the reason; {@code closing} tells a shutdown the world asked for from a crash.
     */
    void follow(Consumer<String> lines, Consumer<String> ended, BooleanSupplier alive, BooleanSupplier closing) {
        stderr.follow(process.getErrorStream());
        reader = Thread.ofPlatform().daemon().name("sim-stdout").start(() -> readLines(lines, ended, closing));
        Thread.ofPlatform().daemon().name("sim-stdin").start(() -> writeLines(ended, alive, closing));
    }

    /** The operating-system id of the process. */
    long pid() {
        return process.pid();
    }

    /** Queues a request line; the writer thread sends it. */
    void send(String line) {
        outbox.add(line);
    }

    /** Drops the lines not written yet (the simulator is dead). */
    void discardQueued() {
        outbox.clear();
    }

    /** Stops the process by force (a hung simulator). */
    void kill() {
        process.destroyForcibly();
    }

    /** Stops the process and everything it started by force (a simulator that does not speak the protocol). */
    void killTree() {
        process.descendants().forEach(ProcessHandle::destroyForcibly);
        process.destroyForcibly();
    }

    /** Waits up to 3 s for the process to exit, then stops it by force (and waits up to 3 s more). */
    void awaitExit() {
        try {
            if (!process.waitFor(3, TimeUnit.SECONDS)) {
                process.destroyForcibly().waitFor(3, TimeUnit.SECONDS);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            process.destroyForcibly();
        }
    }

    /** Waits up to {@code timeout} for the reader to have handed over the last line and the reason. */
    void joinReader(Duration timeout) throws InterruptedException {
        reader.join(timeout);
    }

    private void writeLines(Consumer<String> ended, BooleanSupplier alive, BooleanSupplier closing) {
        try {
            while (alive.getAsBoolean()) {
                String line = outbox.poll(200, TimeUnit.MILLISECONDS);
                if (line == null) {
                    continue;
                }
                stdin.write(line);
                stdin.write('\n');
                if (outbox.isEmpty()) {
                    stdin.flush();
                }
                LOG.debug("-> {}", line);
            }
        } catch (IOException e) {
            ended.accept(reasonAfterBrokenPipe(e, closing));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private void readLines(Consumer<String> lines, Consumer<String> ended, BooleanSupplier closing) {
        try (BufferedReader in = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
            String line;
            while ((line = in.readLine()) != null) {
                lines.accept(line);
            }
        } catch (IOException e) {
            LOG.debug("Simulator stdout closed: {}", e.getMessage());
        }
        ended.accept(reasonAfterEof(closing));
    }

    private String reasonAfterEof(BooleanSupplier closing) {
        try {
            if (process.waitFor(2, TimeUnit.SECONDS)) {
                return exitReason(process.exitValue(), closing);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        process.destroyForcibly();
        return "simulator closed its output and was stopped";
    }

    private String reasonAfterBrokenPipe(IOException e, BooleanSupplier closing) {
        try {
            if (process.waitFor(1, TimeUnit.SECONDS)) {
                return exitReason(process.exitValue(), closing);
            }
        } catch (InterruptedException ie) {
            Thread.currentThread().interrupt();
        }
        return "simulator pipe broke (" + e.getMessage() + ")";
    }

    private String exitReason(int code, BooleanSupplier closing) {
        stderr.drain();
        return closing.getAsBoolean() && code == 0 ? "simulator was shut down" : stderr.exitReason(code);
    }
}
