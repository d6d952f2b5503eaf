package org.kicnp.robots;

import org.kicnp.agent.ActionHandle;
import org.kicnp.agent.AgentBase;
import org.kicnp.agent.AgentException;
import org.kicnp.agent.AgentOptions;
import org.kicnp.core.Frame;
import org.kicnp.core.Value;
import org.kicnp.protocol.Message.Command;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The agent of one simulated robot (section 3.3): registers the robot's capability frames, hands each platform
 * command to its {@link RobotDriver} (which converts it into a simulator command) and reports the driver's
 * {@link Feedback} through the command's {@link ActionHandle} and its {@link SensorSignal}s as {@code sensor}
 * messages. The four robots are the four subclasses; only Robovie adds something (face recognition).
 */
public abstract sealed class RobotAgent extends AgentBase permits RobovieAgent, PinoAgent, ScoutAgent, AiboAgent {
    private static final Logger LOG = LoggerFactory.getLogger(RobotAgent.class);

    private static final Pattern SIM_REQUEST = Pattern.compile("^request 'j\\d+': ");
    private static final Pattern SIM_ID = Pattern.compile("'(j\\d+)'");
    private static final String REFUSED = "field 'action' refused: ";

    private final RobotDriver driver;
    /** How long a command waits for the robot to stop what it was asked to stop before it starts anyway. */
    static final Duration STOPPING_WAIT = Duration.ofSeconds(2);
    /** The commands running in the simulator, by command id, so that a cancel can halt the robot. */
    private final Map<String, Running> commands = new ConcurrentHashMap<>();

    /** A command running in the simulator: its handle (which knows whether a cancel was asked) and its end. */
    private record Running(ActionHandle handle, CompletableFuture<Feedback> end) {
    }

    /** {@code driverFor} makes the driver given where its signals go (this agent). */
    RobotAgent(AgentOptions options, Function<Consumer<SensorSignal>, RobotDriver> driverFor) {
        super(options);
        this.driver = Objects.requireNonNull(driverFor.apply(this::signal), "driver");
    }

    /** The driver of the simulated robot behind this agent. */
    public final RobotDriver driver() {
        return driver;
    }

    @Override protected final List<Frame> capabilities() {
        return driver.capabilities();
    }

    /**
     * Runs a command in the simulator. A command that comes while the robot is stopping another one (a cancel was
     * asked, the robot has not halted yet) first waits, up to {@link #STOPPING_WAIT}, for it to halt, so that "stop,
     * then go elsewhere" (a preemption, as the platform sends it: the cancel first, then the new command) does not
     * find the robot's part still busy with the old action.
     */
    @Override protected void onCommand(Command command, ActionHandle handle) {
        awaitStopping();
        LOG.info("Agent '{}' runs command '{}': {} {}", name(), command.id(), command.action(), command.args());
        CompletableFuture<Feedback> end = driver.execute(command.action(), command.args(),
                f -> report(command, handle, f));
        if (!end.isDone()) {
            Running running = new Running(handle, end);
            commands.put(command.id(), running);
            end.whenComplete((f, e) -> commands.remove(command.id(), running));
        }
    }

    private void awaitStopping() {
        long deadline = System.nanoTime() + STOPPING_WAIT.toNanos();
        for (Running r : commands.values()) {
            if (!r.handle().isCancelRequested()) {
                continue;
            }
            try {
                r.end().get(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
            } catch (TimeoutException e) {
                LOG.warn("Agent '{}': command '{}' has not stopped within {} ms of its cancel; the next command "
                        + "starts anyway.", name(), r.handle().command().id(), STOPPING_WAIT.toMillis());
            } catch (ExecutionException e) {
                // It ended, badly: the robot is free either way.
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
    }

    /**
     * The platform's id of the command this agent runs as the simulator's action {@code simActionId} (the simulator
     * numbers actions its own way); empty when it runs no such command.
     */
    public Optional<String> commandOf(String simActionId) {
        for (Map.Entry<String, Running> e : commands.entrySet()) {
            if (driver.simActionId(e.getValue().end()).filter(simActionId::equals).isPresent()) {
                return Optional.of(e.getKey());
            }
        }
        return Optional.empty();
    }

    /** Halts the robot in the simulator, which ends the action; it is then reported cancelled (see {@link #report}). */
    @Override protected void onCancel(ActionHandle handle, String reason) {
        Running running = commands.get(handle.command().id());
        if (running == null || !driver.cancel(running.end())) {
            super.onCancel(handle, reason);
        }
    }

    private void report(Command command, ActionHandle handle, Feedback feedback) {
        try {
            switch (feedback) {
                case Feedback.Started s -> handle.started();
                case Feedback.Progress p -> handle.progress(p.fraction(), p.note());
                case Feedback.Ended e -> handle.ended(e.result());
                case Feedback.Failed f when handle.isCancelRequested() -> {
                    LOG.info("Agent '{}': command '{}' ({}) stopped on a cancel: {}", name(), command.id(),
                            command.action(), f.reason());
                    handle.cancelled(handle.cancelReason().orElse(f.reason()));
                }
                case Feedback.Failed f -> {
                    String reason = inPlatformTerms(f.reason());
                    LOG.warn("Agent '{}': command '{}' ({}) failed: {}", name(), command.id(), command.action(), reason);
                    handle.failed(reason);
                }
            }
        } catch (AgentException e) {
            LOG.warn("Agent '{}' could not report {} of command '{}': {}", name(),
                    feedback.getClass().getSimpleName().toLowerCase(java.util.Locale.ROOT), command.id(), e.getMessage());
        }
    }

    /**
     * A simulator refusal as the platform's user reads it: without the simulator's own request id, and with the
     * simulator's id of a running action replaced by the platform's id of its command ("busy with go_to 'a12'").
     */
    private String inPlatformTerms(String reason) {
        String r = SIM_REQUEST.matcher(reason).replaceFirst("");
        if (r.startsWith(REFUSED)) {
            r = r.substring(REFUSED.length() - "refused: ".length());
        }
        return SIM_ID.matcher(r).replaceAll(m -> Matcher.quoteReplacement(
                "'" + commandOf(m.group(1)).orElse(m.group(1)) + "'"));
    }

    private void signal(SensorSignal signal) {
        if (signal.sensor().equals("simulator")) {
            LOG.error("Agent '{}': the simulator is gone ({}); its commands fail from now on.", name(),
                    signal.values().get(1).text());
        }
        if (!isConnected()) {
            LOG.debug("Agent '{}' is not connected; {} signal dropped.", name(), signal.sensor());
            return;
        }
        try {
            sensor(signal.sensor(), signal.values().toArray(Value[]::new));
        } catch (AgentException e) {
            LOG.debug("Agent '{}' could not send its {} signal: {}", name(), signal.sensor(), e.getMessage());
        }
    }

    /** Stops listening to the simulator and disconnects; the simulator itself is closed by its owner. */
    @Override public void close() {
        driver.close();
        super.close();
    }
}
