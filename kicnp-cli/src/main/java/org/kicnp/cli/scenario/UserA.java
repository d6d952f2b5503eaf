package org.kicnp.cli.scenario;

import java.time.Duration;
import java.util.Map;
import java.util.Optional;
import java.util.function.Consumer;
import org.kicnp.agent.AgentOptions;
import org.kicnp.agent.UserAgent;
import org.kicnp.cli.platform.Platform;
import org.kicnp.cli.platform.PlatformEvent;
import org.kicnp.language.Expectation;
import org.kicnp.language.ParserAgent;
import org.kicnp.protocol.AgentKind;
import org.kicnp.robots.SimRequest;
import org.kicnp.robots.SimWorld;

/**
 * User A: a person in the simulated room (who appears before Robovie's eye cameras and leaves again) and a
 * wireless microphone: a user agent, named like the person in the room, that relays what they say to the
 * sentence parser. A script or a person at the terminal drives it. The microphone hears Robovie too: after a
 * question for a name or a drink ("What is your name?", "What do you want to drink?") it relays with subject
 * {@code utterance:name} or {@code utterance:drink}, so that an answer of a name or a drink alone ("Ken.",
 * "Lemonade.") is understood as one.
 */
public final class UserA implements AutoCloseable {
    private final Platform platform;
    private final SimWorld sim;
    private final String simName;
    private final UserAgent mic;
    private final Consumer<PlatformEvent> listener = this::heard;
    /** What Robovie's last line asked for. */
    private volatile Expectation asked = Expectation.NONE;

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
        UserA user = new UserA(platform, sim, simName, mic);
        platform.events().subscribe(user.listener);
        return user;
    }

    /** Robovie's speech (the {@code utterance} events): remembers whether it asked for a name or a drink. */
    private void heard(PlatformEvent e) {
        if (e.kind().equals("utterance")) {
            asked = Expectation.after(RunRecord.firstValue(e));
        }
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
     * ({@code SaidName}, {@code SaidDrinkRequest}, …) with this user as the speaker; after Robovie asked for a name
     * or a drink, the parser is told so.
     */
    public void say(String text) {
        platform.events().record("user_said", Map.of("user", simName, "text", text));
        mic.relayTo("parser", ParserAgent.subject(asked), text);
    }

    /** What the parser answered when it did not understand (its "say again" replies), oldest first. */
    public java.util.List<String> sayAgainReplies() {
        return mic.relays().stream().filter(r -> r.subject().equals(ParserAgent.SAY_AGAIN))
                .map(r -> r.body()).toList();
    }

    @Override public void close() {
        platform.events().unsubscribe(listener);
        mic.close();
    }
}
