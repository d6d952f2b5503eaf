package org.kicnp.robots;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayDeque;
import java.util.Deque;

/**
 * The simulator's stderr: each line goes to the log at the level the simulator gave it ({@code kicnp.sim} logger),
 * and the last few are kept so that an unexpected exit can quote the simulator's last words.
 */
final class SimStderr {
    private static final Logger LOG = LoggerFactory.getLogger(SimStderr.class);
    private static final Logger SIM_LOG = LoggerFactory.getLogger("kicnp.sim");
    private static final int KEPT = 5;

    private final Deque<String> last = new ArrayDeque<>();
    private volatile Thread reader;

    /** Reads the stream to its end on a daemon thread. */
    void follow(InputStream stderr) {
        reader = Thread.ofPlatform().daemon().name("sim-stderr").start(() -> read(stderr));
    }

    /** Once the process has exited: waits briefly for its last lines, so an exit reason can quote them. */
    void drain() {
        Thread t = reader;
        if (t == null) {
            return;
        }
        try {
            t.join(Duration.ofSeconds(1));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private void read(InputStream stderr) {
        try (BufferedReader in = new BufferedReader(new InputStreamReader(stderr, StandardCharsets.UTF_8))) {
            String line;
            while ((line = in.readLine()) != null) {
                keep(line);
                if (line.startsWith("ERROR") || line.startsWith("CRITICAL") || line.startsWith("Traceback")) {
                    SIM_LOG.error("{}", line);
                } else if (line.startsWith("WARNING")) {
                    SIM_LOG.warn("{}", line);
                } else {
                    SIM_LOG.info("{}", line);
                }
            }
        } catch (IOException e) {
            LOG.debug("Simulator stderr closed: {}", e.getMessage());
        }
    }

    private synchronized void keep(String line) {
        if (last.size() == KEPT) {
            last.removeFirst();
        }
        last.addLast(line);
    }

    /** How an exit code reads in a failure reason: the signal for a kill, the last words for an error exit. */
    synchronized String exitReason(int code) {
        String reason = "simulator exited with code " + code;
        if (code > 128) {
            return reason + " (signal " + (code - 128) + ")";
        }
        if (code != 0 && !last.isEmpty()) {
            return reason + "; its last words: " + String.join(" | ", last);
        }
        return reason;
    }
}
