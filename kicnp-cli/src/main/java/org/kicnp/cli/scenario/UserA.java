package org.kicnp.cli.scenario;

import java.time.Duration;
import java.util.Map;
import java.util.Optional;
import org.kicnp.agent.AgentOptions;
import org.kicnp.agent.UserAgent;
import org.kicnp.cli.platform.Platform;
import org.kicnp.language.ParserAgent;
import org.kicnp.protocol.AgentKind;
import org.kicnp.robots.SimRequest;
import org.kicnp.robots.SimWorld;

/**
 * User A: a person in the simulated room (who appears before Robovie's eye cameras and leaves again) and a
 * wireless microphone: a user agent, named like the person in the room, that relays what they say to the
 * sentence parser. A script or a person at the terminal drives it.
 */
public final class UserA implements AutoCloseable {
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
        UserAgent mic = new UserAgent(AgentOptions.of("127.0.0.1", platform.gatewayPort(), simName, AgentKind.USER,
                platform.token(simName)));
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

    /**
     * Says something into the microphone: the sentence goes to the parser agent, which asserts its case frame
     * ({@code SaidName}, {@code SaidDrinkRequest}, …) with this user as the speaker.
     */
    public void say(String text) {
        platform.events().record("user_said", Map.of("user", simName, "text", text));
        mic.relayTo("parser", ParserAgent.SUBJECT, text);
    }

    /** What the parser answered when it did not understand (its "say again" replies), oldest first. */
    public java.util.List<String> sayAgainReplies() {
        return mic.relays().stream().filter(r -> r.subject().equals(ParserAgent.SAY_AGAIN))
                .map(r -> r.body()).toList();
    }

    @Override public void close() {
        mic.close();
    }
}
