package org.kicnp.cli.platform;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;
import java.util.function.Function;
import org.kicnp.editor.SimulatorState;
import org.kicnp.editor.Subscription;
import org.kicnp.editor.WorldSnapshot;
import org.kicnp.editor.WorldSnapshot.Room;
import org.kicnp.editor.WorldView;
import org.kicnp.robots.SimEvent;
import org.kicnp.robots.SimRequest;
import org.kicnp.robots.SimWorld;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The editor's World panel over the live simulator. The platform starts before the simulator ({@code demo} and
 * {@code replay} start it once the platform and editor are up), so the view starts empty ({@code GET /api/world}
 * answers 204) and is {@linkplain #attach attached} to the simulator later: it then asks the simulator to stream its
 * state and turns each {@code state} event into a {@link WorldSnapshot} for the subscribers. The simulator numbers
 * the actions it runs its own way; given the robot agents' mapping, a running action is shown under the platform's
 * command id, the id the editor's "Wrong" and "Stop" name.
 */
public final class LiveWorldView implements WorldView {
    private static final Logger LOG = LoggerFactory.getLogger(LiveWorldView.class);

    /** Simulated time between two streamed states: five pictures per simulated second. */
    static final int STREAM_PERIOD_MS = 200;

    private final AtomicReference<WorldSnapshot> latest = new AtomicReference<>();
    private final Listeners<WorldSnapshot> listeners = new Listeners<>();
    private volatile Room room = Room.SIMULATOR;
    private volatile Function<String, Optional<String>> commandIds = simId -> Optional.empty();

    @Override public Optional<WorldSnapshot> latest() {
        return Optional.ofNullable(latest.get());
    }

    @Override public Subscription onSnapshot(Consumer<WorldSnapshot> listener) {
        return listeners.add(listener);
    }

    /**
     * Follows {@code sim}: listens to its {@code state} events and asks it to stream them every
     * {@value #STREAM_PERIOD_MS} ms of simulated time. Closing the result stops following (the simulator keeps
     * streaming until it stops).
     *
     * @throws org.kicnp.robots.SimulatorException when the simulator refuses or has died
     */
    public AutoCloseable attach(SimWorld sim) {
        return attach(sim, simId -> Optional.empty());
    }

    /**
     * As {@link #attach(SimWorld)}, showing each running action under the platform command id {@code commandIds}
     * gives for the simulator's action id (under the simulator's id where it gives none).
     */
    public AutoCloseable attach(SimWorld sim, Function<String, Optional<String>> commandIds) {
        Objects.requireNonNull(sim, "sim");
        this.commandIds = Objects.requireNonNull(commandIds, "commandIds");
        AutoCloseable registration = sim.addListener(this::onEvent);
        sim.call(new SimRequest.Stream(true, STREAM_PERIOD_MS));
        LOG.info("The editor's world view follows the simulator (pid {}).", sim.pid());
        return registration;
    }

    /** Takes the room from the simulator's {@code hello} event (the simulator's default room until then). */
    public void hello(JsonNode hello) {
        room = SimulatorState.room(hello);
    }

    /** Takes one simulator {@code state} event: it becomes the latest snapshot and goes to every subscriber. */
    public void state(JsonNode state) {
        WorldSnapshot snapshot = withCommandIds(SimulatorState.snapshot(state, room));
        latest.set(snapshot);
        listeners.emit(snapshot);
    }

    private WorldSnapshot withCommandIds(WorldSnapshot s) {
        List<WorldSnapshot.Robot> robots = s.robots().stream().map(r -> new WorldSnapshot.Robot(r.name(), r.kind(),
                r.x(), r.y(), r.headingDeg(), r.actions().stream().map(a -> new WorldSnapshot.RunningAction(a.part(),
                        commandIds.apply(a.id()).orElse(a.id()), a.action())).toList(), r.state())).toList();
        return new WorldSnapshot(s.time(), s.room(), robots, s.users(), s.cups(), s.obstacles());
    }

    private void onEvent(SimEvent event) {
        if (event instanceof SimEvent.State s) {
            try {
                state(stateEvent(s));
            } catch (RuntimeException e) {
                LOG.warn("A simulator state at t={} could not be shown: {}", s.t(), e.getMessage());
            }
        }
    }

    /** The state event as the simulator sent it: {@link SimEvent.State#world} is the whole event or its body. */
    private static JsonNode stateEvent(SimEvent.State s) {
        if ("state".equals(s.world().path("type").asText())) {
            return s.world();
        }
        var node = s.world().deepCopy();
        if (node instanceof ObjectNode o) {
            o.put("type", "state");
            o.put("t", s.t());
            return o;
        }
        throw new IllegalArgumentException("A simulator state is not a JSON object.");
    }
}
