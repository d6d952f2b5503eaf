package org.kicnp.cli.scenario;

import java.time.Duration;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicInteger;
import org.kicnp.agent.AgentOptions;
import org.kicnp.agent.UserAgent;
import org.kicnp.cli.platform.Platform;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.kicnp.protocol.AgentKind;
import org.kicnp.robots.SimRequest;
import org.kicnp.robots.SimWorld;

/**
 * User A: a person in the simulated room (who appears before Robovie's eye cameras and leaves again) and a
 * wireless microphone, a user agent that asserts what they say as a {@code UserSaid} instance with the speaker's
 * id. A script or a person at the terminal drives it.
 */
public final class UserA implements AutoCloseable {
    private static final AtomicInteger SAID = new AtomicInteger();

    private final Platform platform;
    private final SimWorld sim;
    private final String simName;
    private final UserAgent mic;

    private UserA(Platform platform, SimWorld sim, String simName, UserAgent mic) {
        this.platform = platform;
        this.sim = sim;
        this.simName = simName;
        this.mic = mic;
    }

    public static UserA connect(Platform platform, SimWorld sim, String simName) {
        UserAgent mic = new UserAgent(AgentOptions.of("127.0.0.1", platform.gatewayPort(), "user", AgentKind.USER,
                platform.token("user")));
        mic.startAndAwait(Duration.ofSeconds(30));
        return new UserA(platform, sim, simName, mic);
    }

    /** Walks in at the door and stops before Robovie's eye cameras, facing it. */
    public void appear() {
        sim.call(new SimRequest.SpawnUser(simName, 4.0, 0.6, 90, Optional.empty()));
        sim.call(new SimRequest.MoveUser(simName, 4.0, 2.0, Optional.of(90.0), Optional.of(0.8)));
        platform.events().record("user_moved", Map.of("user", simName, "what", "walks in and faces Robovie"));
    }

    /** Leaves the room. */
    public void leave() {
        sim.call(new SimRequest.RemoveUser(simName));
        platform.events().record("user_moved", Map.of("user", simName, "what", "leaves the room"));
    }

    /** Says something into the microphone. */
    public void say(String text) {
        platform.events().record("user_said", Map.of("user", simName, "text", text));
        mic.assertFrame(Frame.instance("said-" + SAID.incrementAndGet() + "-" + System.nanoTime(), "UserSaid")
                .slot(Slot.ofValue("text", DataType.STRING, Value.of(text)))
                .slot(Slot.ofValue("speaker", DataType.STRING, Value.of(simName)))
                .build());
    }

    @Override public void close() {
        mic.close();
    }
}
