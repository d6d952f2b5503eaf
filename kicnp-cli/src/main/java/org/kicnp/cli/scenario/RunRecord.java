package org.kicnp.cli.scenario;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Consumer;
import java.util.function.Predicate;
import org.kicnp.cli.platform.PlatformEvent;

/**
 * Everything a run's event log said, kept in order, with waiting ("until Robovie has said …") and the views the
 * checks need: each robot command with when it was sent, started and finished, and Robovie's lines.
 */
public final class RunRecord implements Consumer<PlatformEvent> {
    private final ReentrantLock lock = new ReentrantLock();
    private final Condition grew = lock.newCondition();
    private final List<PlatformEvent> events = new ArrayList<>();

    /** One robot command and its fate. Times are {@link System#nanoTime()}; 0 when it did not happen. */
    public record Step(String id, String robot, String action, String args, String frame, long sent, long started,
                       long finished, String outcome, String detail) {
        public boolean ended() {
            return outcome.equals("ended");
        }
    }

    @Override public void accept(PlatformEvent e) {
        lock.lock();
        try {
            events.add(e);
            grew.signalAll();
        } finally {
            lock.unlock();
        }
    }

    public List<PlatformEvent> events() {
        lock.lock();
        try {
            return List.copyOf(events);
        } finally {
            lock.unlock();
        }
    }

    /** Waits for an event that matches, among all recorded so far and those to come. */
    public PlatformEvent await(Predicate<PlatformEvent> match, Duration timeout, String what) throws TimeoutException,
            InterruptedException {
        long deadline = System.nanoTime() + timeout.toNanos();
        lock.lock();
        try {
            int seen = 0;
            while (true) {
                for (; seen < events.size(); seen++) {
                    if (match.test(events.get(seen))) {
                        return events.get(seen);
                    }
                }
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    throw new TimeoutException("Waited " + timeout.toSeconds() + " s for " + what + " in vain.");
                }
                grew.awaitNanos(left);
            }
        } finally {
            lock.unlock();
        }
    }

    /** Waits until a robot has begun to say a line containing {@code text}. */
    public PlatformEvent awaitLine(String text, Duration timeout) throws TimeoutException, InterruptedException {
        return await(e -> e.kind().equals("utterance") && firstValue(e).contains(text), timeout, "the line '" + text + "'");
    }

    /** Waits until the command issued by a behavior frame has finished (ended or failed). */
    public Step awaitFinished(String frame, Duration timeout) throws TimeoutException, InterruptedException {
        await(e -> e.kind().equals("feedback") && !e.text("stage").equals("started")
                && step(e.text("id")).map(s -> s.frame().equals(frame)).orElse(false), timeout,
                "the end of " + frame + "'s action");
        return steps().stream().filter(s -> s.frame().equals(frame) && s.finished() > 0).findFirst().orElseThrow();
    }

    static String firstValue(PlatformEvent e) {
        Object v = e.fields().get("values");
        return v instanceof List<?> l && !l.isEmpty() ? String.valueOf(l.getFirst()) : "";
    }

    /** The lines the robots said, in order. */
    public List<String> lines() {
        return events().stream().filter(e -> e.kind().equals("utterance")).map(RunRecord::firstValue).toList();
    }

    public Optional<Step> step(String id) {
        return steps().stream().filter(s -> s.id().equals(id)).findFirst();
    }

    /** The robot commands in the order they were sent. */
    public List<Step> steps() {
        List<Step> out = new ArrayList<>();
        List<PlatformEvent> all = events();
        for (PlatformEvent c : all) {
            if (!c.kind().equals("command")) {
                continue;
            }
            String id = c.text("id");
            long started = 0;
            long finished = 0;
            String outcome = "";
            String detail = "";
            for (PlatformEvent f : all) {
                if (!f.kind().equals("feedback") || !f.text("id").equals(id)) {
                    continue;
                }
                switch (f.text("stage")) {
                    case "started" -> started = f.nanos();
                    default -> {
                        finished = f.nanos();
                        outcome = f.text("stage");
                        detail = f.text("detail");
                    }
                }
            }
            out.add(new Step(id, c.text("robot"), c.text("action"), c.text("args"), c.text("frame"), c.nanos(),
                    started, finished, outcome, detail));
        }
        return out;
    }

    /** The steps of one behavior frame. */
    public List<Step> stepsOf(String frame) {
        return steps().stream().filter(s -> s.frame().equals(frame)).toList();
    }

    /**
     * The stimulus-to-command latency of every command, in ms: from the last stimulus before it (a user's words,
     * a sensor signal, a robot's feedback) to the command leaving the platform.
     */
    public List<Double> latenciesMillis() {
        List<Double> out = new ArrayList<>();
        long lastStimulus = 0;
        for (PlatformEvent e : events()) {
            switch (e.kind()) {
                case "user_said", "signal" -> lastStimulus = e.nanos();
                case "feedback" -> {
                    if (!e.text("stage").equals("started")) {
                        lastStimulus = e.nanos();
                    }
                }
                case "command" -> {
                    if (lastStimulus > 0) {
                        out.add((e.nanos() - lastStimulus) / 1e6);
                    }
                }
                default -> { }
            }
        }
        return out;
    }

    /** "p50 1.2 ms, p99 8.4 ms (n=23)". */
    public String latencySummary() {
        List<Double> l = new ArrayList<>(latenciesMillis());
        if (l.isEmpty()) {
            return "no commands";
        }
        l.sort(Double::compare);
        return String.format(Locale.ROOT, "stimulus-to-command latency p50 %.1f ms, p99 %.1f ms (n=%d)",
                percentile(l, 50), percentile(l, 99), l.size());
    }

    static double percentile(List<Double> sorted, int p) {
        int i = (int) Math.ceil(p / 100.0 * sorted.size()) - 1;
        return sorted.get(Math.max(0, Math.min(sorted.size() - 1, i)));
    }
}
