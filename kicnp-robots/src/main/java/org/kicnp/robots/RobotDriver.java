package org.kicnp.robots;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.kicnp.core.Frame;
import org.kicnp.core.Value;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;

/**
 * One simulated robot's local control program, as the robot agent sees it: platform commands (an action name and
 * text arguments) become simulator commands; the simulator's action events become {@link Feedback}; its sensor
 * events for this robot become {@link SensorSignal}s. For Robovie, given a {@link FaceRecognizer}, each face seen is
 * recognised here and reported with the user's name or {@code unknown}. Thread-safe.
 */
public final class RobotDriver implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(RobotDriver.class);
    public static final String UNKNOWN = "unknown";
    private static final double PROGRESS_PERIOD_S = 1.0;

    private final SimWorld world;
    private final RobotModel model;
    private final Optional<FaceRecognizer> faces;
    private final Consumer<SensorSignal> signals;
    private final Map<String, String> trackNames = new ConcurrentHashMap<>();
    private final AutoCloseable subscription;
    /** The simulator action behind each command this driver runs, until it ends. */
    private final Map<CompletableFuture<Feedback>, SimAction> actions = new ConcurrentHashMap<>();
    private volatile FaceVector lastFace;

    private RobotDriver(SimWorld world, RobotModel model, Optional<FaceRecognizer> faces, Consumer<SensorSignal> signals) {
        this.world = world;
        this.model = model;
        this.faces = faces;
        this.signals = signals;
        this.subscription = world.addListener(this::onEvent);
    }

    /** A driver for {@code model}'s robot in {@code world}, sending its sensor signals to {@code signals}. */
    public static RobotDriver attach(SimWorld world, RobotModel model, Consumer<SensorSignal> signals) {
        return new RobotDriver(Objects.requireNonNull(world, "world"), Objects.requireNonNull(model, "model"),
                Optional.empty(), Objects.requireNonNull(signals, "signals"));
    }

    /** As {@link #attach(SimWorld, RobotModel, Consumer)}, recognising the faces the robot's cameras see. */
    public static RobotDriver attach(SimWorld world, RobotModel model, FaceRecognizer faces, Consumer<SensorSignal> signals) {
        return new RobotDriver(Objects.requireNonNull(world, "world"), Objects.requireNonNull(model, "model"),
                Optional.of(faces), Objects.requireNonNull(signals, "signals"));
    }

    public RobotModel model() {
        return model;
    }

    public String name() {
        return model.name();
    }

    /** The capability frames the agent registers. */
    public List<Frame> capabilities() {
        return model.capabilityFrames();
    }

    /** Whether the simulator behind this robot is running. */
    public boolean alive() {
        return world.alive();
    }

    /** The last face the robot's cameras reported, for learning a new user's face. */
    public Optional<FaceVector> lastFace() {
        return Optional.ofNullable(lastFace);
    }

    /**
     * Runs a platform command: {@code feedback} gets started, progress, then ended or failed (a refused command,
     * such as an unknown action, a bad argument or a busy part, fails without starting). The future completes with
     * the terminal feedback.
     */
    public CompletableFuture<Feedback> execute(String action, Map<String, String> args, Consumer<Feedback> feedback) {
        Objects.requireNonNull(action, "action");
        Objects.requireNonNull(args, "args");
        Objects.requireNonNull(feedback, "feedback");
        Optional<String> dead = world.deathReason();
        if (dead.isPresent()) {
            return finish(feedback, new Feedback.Failed(dead.get()));
        }
        Optional<ActionSpec> spec = model.action(action);
        if (spec.isEmpty()) {
            return finish(feedback, new Feedback.Failed("Robot '" + name() + "' has no action '" + action + "'; it offers "
                    + model.actions().stream().map(ActionSpec::frameName).toList() + "."));
        }
        Map<String, Object> simArgs;
        try {
            simArgs = spec.get().toArgs(args);
        } catch (IllegalArgumentException e) {
            return finish(feedback, new Feedback.Failed(e.getMessage()));
        }
        SimRequest.Command command = new SimRequest.Command(name(), spec.get().simAction(), simArgs, Optional.empty(),
                Optional.of(PROGRESS_PERIOD_S));
        ProgressMeter meter = new ProgressMeter();
        CompletableFuture<Feedback> done = new CompletableFuture<>();
        try {
            SimAction running = world.command(command, update -> {
                Feedback f = toFeedback(update, meter);
                feedback.accept(f);
                if (f.terminal()) {
                    done.complete(f);
                }
            });
            actions.put(done, running);
            done.whenComplete((f, e) -> actions.remove(done));
        } catch (SimulatorExitedException e) {
            return finish(feedback, new Feedback.Failed(world.deathReason().orElse(e.getMessage())));
        } catch (IllegalArgumentException e) { // too long for the protocol: a refusal, as a bad argument is
            return finish(feedback, new Feedback.Failed(e.getMessage()));
        }
        return done;
    }

    /** The simulator's id of a command {@link #execute} is running; empty once it has ended. */
    public Optional<String> simActionId(CompletableFuture<Feedback> command) {
        return Optional.ofNullable(actions.get(command)).map(SimAction::id);
    }

    /**
     * Stops a command {@link #execute} is running: the simulator halts the robot and ends the action as failed.
     *
     * @param command the future {@link #execute} returned
     * @return false when it is not running (it has ended, or the simulator is gone)
     */
    public boolean cancel(CompletableFuture<Feedback> command) {
        SimAction running = actions.get(command);
        if (running == null || !world.alive()) {
            return false;
        }
        try {
            world.request(new SimRequest.Cancel(name(), running.id()));
            return true;
        } catch (SimulatorExitedException e) {
            return false;
        }
    }

    private static CompletableFuture<Feedback> finish(Consumer<Feedback> feedback, Feedback terminal) {
        feedback.accept(terminal);
        return CompletableFuture.completedFuture(terminal);
    }

    private static Feedback toFeedback(ActionUpdate update, ProgressMeter meter) {
        return switch (update) {
            case ActionUpdate.Started s -> {
                meter.started(s.args());
                yield new Feedback.Started();
            }
            case ActionUpdate.Progress p -> new Feedback.Progress(meter.fraction(p), note(p.body()));
            case ActionUpdate.Ended e -> new Feedback.Ended(e.result().toString());
            case ActionUpdate.Failed f -> new Feedback.Failed(f.reason());
        };
    }

    private static String note(JsonNode body) {
        ObjectNode copy = body.deepCopy();
        copy.remove(List.of("type", "id", "robot", "action", "t"));
        return copy.toString();
    }

    /**
     * Turns the simulator's progress (a fraction, or a remaining distance or gap) into a fraction done. A gap
     * ({@code approach_user}) closes down to the asked {@code distance_m}, not to zero.
     */
    private static final class ProgressMeter {
        private double first = Double.NaN;
        private double goal;

        synchronized void started(JsonNode args) {
            JsonNode d = args.get("distance_m");
            goal = d != null && d.isNumber() ? d.asDouble() : 0;
        }

        synchronized double fraction(ActionUpdate.Progress p) {
            if (p.fraction().isPresent()) {
                return clamp(p.fraction().get());
            }
            boolean remaining = p.body().has("remaining_m");
            JsonNode left = remaining ? p.body().get("remaining_m") : p.body().get("gap_m");
            if (left == null || !left.isNumber()) {
                return 0;
            }
            double toGo = left.asDouble() - (remaining ? 0 : goal);
            if (Double.isNaN(first)) {
                first = toGo + 1e-9;
                return 0;
            }
            return clamp(1 - toGo / first);
        }

        private static double clamp(double v) {
            return Math.max(0, Math.min(1, v));
        }
    }

    private void onEvent(SimEvent event) {
        List<SensorSignal> out = new ArrayList<>(1);
        switch (event) {
            case SimEvent.Face f when f.robot().equals(name()) -> out.add(face(f));
            case SimEvent.Bumper b when b.robot().equals(name()) -> out.add(SensorSignal.of("bumper",
                    Value.of(b.pressed()), Value.of(b.bumper()), Value.of(b.contact().orElse(""))));
            case SimEvent.Arrival a when a.robot().equals(name()) -> out.add(SensorSignal.of("arrival",
                    Value.of(a.user().orElse("point")), Value.of(a.x()), Value.of(a.y()), Value.of(a.headingDeg())));
            case SimEvent.Fall f when f.robot().equals(name()) -> out.add(SensorSignal.of("fall", Value.of(f.contact())));
            case SimEvent.Utterance u when u.robot().equals(name()) -> out.add(SensorSignal.of("utterance",
                    Value.of(u.text()), Value.of(u.durationS())));
            case SimEvent.Exited x -> out.add(SensorSignal.of("simulator", Value.of("exited"), Value.of(x.reason())));
            default -> { }
        }
        for (SensorSignal s : out) {
            try {
                signals.accept(s);
            } catch (RuntimeException e) {
                LOG.warn("Robot '{}' could not report its {} signal: {}", name(), s.sensor(), e.getMessage());
            }
        }
    }

    private SensorSignal face(SimEvent.Face f) {
        FaceVector descriptor = FaceVector.of(f.face());
        if (!f.seen()) {
            String name = Optional.ofNullable(trackNames.remove(f.track())).orElse(UNKNOWN);
            return SensorSignal.of("face_lost", Value.of(name), Value.of(f.track()));
        }
        lastFace = descriptor;
        String name = faces.flatMap(r -> r.recognize(descriptor)).map(FaceRecognizer.Match::name).orElse(UNKNOWN);
        trackNames.put(f.track(), name);
        LOG.info("Robot '{}' sees face {} at {} m: {}", name(), f.track(), f.distanceM(), name);
        List<Value> components = descriptor.toList().stream().map(Value::of).toList();
        return SensorSignal.of("face_seen", Value.of(name), new Value.Lst(components), Value.of(f.distanceM()),
                Value.of(f.bearingDeg()), Value.of(f.track()));
    }

    /** Stops listening to the world (the world itself is closed by its owner). */
    @Override public void close() {
        try {
            subscription.close();
        } catch (Exception e) {
            LOG.debug("Closing the subscription of '{}': {}", name(), e.toString());
        }
    }
}
