package org.kicnp.cli.scenario;

import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import org.kicnp.agent.AgentBase;
import org.kicnp.agent.AgentOptions;
import org.kicnp.cli.platform.Platform;
import org.kicnp.language.ParserAgent;
import org.kicnp.language.SentenceParser;
import org.kicnp.protocol.AgentKind;
import org.kicnp.robots.AiboAgent;
import org.kicnp.robots.FaceRecognizer;
import org.kicnp.robots.PinoAgent;
import org.kicnp.robots.RobotAgent;
import org.kicnp.robots.RobovieAgent;
import org.kicnp.robots.ScoutAgent;
import org.kicnp.robots.SimOptions;
import org.kicnp.robots.SimWorld;

/**
 * The simulated room (the pymunk simulator as a subprocess), the four robot agents and the sentence parser's
 * agent, connected to a platform's
 * gateway with the tokens of its agent file. Robovie's recogniser follows the knowledge base's learned faces
 * ({@link FaceBook}).
 */
public final class RobotWorld implements AutoCloseable {
    private static final Duration CONNECT = Duration.ofSeconds(30);

    private final SimWorld sim;
    /** Read by the world view's thread while agents connect: copied on write. */
    private final List<AgentBase> agents = new CopyOnWriteArrayList<>();
    private final FaceBook faces;

    private RobotWorld(SimWorld sim, FaceBook faces) {
        this.sim = sim;
        this.faces = faces;
    }

    public static RobotWorld start(Platform platform, long seed, double timeScale) {
        SimWorld sim = SimWorld.start(SimOptions.defaults().withSeed(seed).withTimeScale(timeScale));
        FaceRecognizer recognizer = FaceRecognizer.create();
        RobotWorld w = new RobotWorld(sim, FaceBook.attach(platform.kb(), recognizer));
        try {
            platform.world().attach(sim, w::commandOf);
            w.connect(new RobovieAgent(options(platform, "robovie"), sim, recognizer));
            w.connect(new PinoAgent(options(platform, "pino"), sim));
            w.connect(new ScoutAgent(options(platform, "scout"), sim));
            w.connect(new AiboAgent(options(platform, "aibo"), sim));
            w.connect(new ParserAgent(AgentOptions.of("127.0.0.1", platform.gatewayPort(), "parser", AgentKind.SERVICE,
                    platform.token("parser")), SentenceParser.standard()));
            return w;
        } catch (RuntimeException e) {
            w.close();
            throw e;
        }
    }

    static AgentOptions options(Platform platform, String agent) {
        return AgentOptions.of("127.0.0.1", platform.gatewayPort(), agent, AgentKind.ROBOT, platform.token(agent));
    }

    private void connect(AgentBase agent) {
        agents.add(agent);
        agent.startAndAwait(CONNECT);
    }

    /** The platform command id a robot agent runs as the simulator's action {@code simActionId}. */
    private Optional<String> commandOf(String simActionId) {
        for (AgentBase a : agents) {
            if (a instanceof RobotAgent r) {
                Optional<String> id = r.commandOf(simActionId);
                if (id.isPresent()) {
                    return id;
                }
            }
        }
        return Optional.empty();
    }

    public SimWorld sim() {
        return sim;
    }

    /** The agent of a robot ({@code "aibo"}), to disconnect it in a failure run. */
    public Optional<AgentBase> agent(String name) {
        return agents.stream().filter(a -> a.getClass().getSimpleName().equalsIgnoreCase(name + "Agent")).findFirst();
    }

    @Override public void close() {
        faces.detach();
        for (AgentBase a : agents.reversed()) {
            try {
                a.close();
            } catch (RuntimeException e) {
                // closing the rest matters more
            }
        }
        sim.close();
    }
}
