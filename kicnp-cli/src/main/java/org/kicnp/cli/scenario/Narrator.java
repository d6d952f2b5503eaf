package org.kicnp.cli.scenario;

import java.io.PrintStream;
import java.util.Map;
import java.util.function.Consumer;
import org.kicnp.cli.platform.PlatformEvent;

/**
 * Prints the run as it happens: what each robot says (in quotes), each command it is given and how it ends, and
 * what User A says. One line per event; the latency of each command from its stimulus is shown in brackets.
 */
public final class Narrator implements Consumer<PlatformEvent> {
    private static final Map<String, String> ROBOTS = Map.of("robovie", "Robovie", "pino", "PINO", "scout", "Scout",
            "aibo", "AIBO");

    private final PrintStream out;
    private final long t0 = System.nanoTime();
    private volatile long lastStimulus;

    public Narrator(PrintStream out) {
        this.out = out;
    }

    static String robot(String agent) {
        return ROBOTS.getOrDefault(agent, agent);
    }

    @Override public void accept(PlatformEvent e) {
        String at = String.format("%6.2fs ", (e.nanos() - t0) / 1e9);
        switch (e.kind()) {
            case "utterance" -> out.println(at + robot(e.text("robot")) + ": \"" + RunRecord.firstValue(e) + "\"");
            case "user_said" -> {
                lastStimulus = e.nanos();
                out.println(at + "User A: \"" + e.text("text") + "\"");
            }
            case "user_moved" -> out.println(at + "(User A " + e.text("what") + ")");
            case "signal" -> {
                lastStimulus = e.nanos();
                if (e.text("sensor").startsWith("face") || e.text("sensor").equals("bumper")) {
                    out.println(at + "  " + robot(e.text("robot")) + " senses " + e.text("sensor") + " " + e.text("values"));
                }
            }
            case "command" -> out.println(at + "  -> " + robot(e.text("robot")) + " " + e.text("action") + " "
                    + e.text("args") + " (" + e.text("frame") + String.format(", %.1f ms", (e.nanos() - lastStimulus) / 1e6) + ")");
            case "feedback" -> {
                if (!e.text("stage").equals("started")) {
                    lastStimulus = e.nanos();
                    out.println(at + "  " + (e.text("stage").equals("ended") ? "ok " : "FAILED ") + robot(e.text("robot"))
                            + " " + e.text("action") + (e.text("stage").equals("ended") ? "" : ": " + e.text("detail")));
                }
            }
            case "script_failed" -> out.println(at + "  script of " + e.text("frame") + " failed: " + e.text("message"));
            default -> { }
        }
        out.flush();
    }
}
