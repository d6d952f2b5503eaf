package org.kicnp.cli;

import org.kicnp.agent.AgentException;
import org.kicnp.agent.AgentOptions;
import org.kicnp.cli.platform.PlatformConfig;
import org.kicnp.protocol.AgentKind;
import org.kicnp.robots.AiboAgent;
import org.kicnp.robots.PinoAgent;
import org.kicnp.robots.RobotAgent;
import org.kicnp.robots.RobovieAgent;
import org.kicnp.robots.ScoutAgent;
import org.kicnp.robots.SimEvent;
import org.kicnp.robots.SimOptions;
import org.kicnp.robots.SimWorld;
import org.kicnp.robots.SimulatorException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Properties;
import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import javax.net.SocketFactory;

/**
 * {@code kicnp robots}: starts the simulated room (the Python simulator) and the agents of Robovie, PINO, Scout and
 * AIBO against a running K-ICNP server, and keeps them running until interrupted, for {@code --for} seconds, or
 * until the simulator dies.
 */
@Command(name = "robots", mixinStandardHelpOptions = true,
        description = "Start the simulator and the four robot agents (robovie, pino, scout, aibo) "
                + "against a running server.")
public final class RobotsCommand implements Callable<Integer> {
    private static final List<String> ROBOTS = List.of("robovie", "pino", "scout", "aibo");
    private static final Duration STOP_WAIT = Duration.ofSeconds(15);
    private static final Duration REGISTER_WAIT = Duration.ofSeconds(15);

    // The port serve listens on by default, so that "serve KB" then "robots" finds it.
    @Option(names = "--gateway", defaultValue = "127.0.0.1:" + PlatformConfig.DEFAULT_GATEWAY_PORT,
            description = "The server, host:port (default ${DEFAULT-VALUE}, where serve listens by default).")
    String gateway;

    @Option(names = "--tokens", defaultValue = "agents.properties",
            description = "Properties file with NAME.token for robovie, pino, scout and aibo (default ${DEFAULT-VALUE}; "
                    + "serve writes it to KB_DIR/.kicnp/agents.properties).")
    Path tokens;

    @Option(names = "--seed", defaultValue = "42",
            description = "Simulator seed: faces and sensor noise (default ${DEFAULT-VALUE}).")
    long seed;

    @Option(names = "--time-scale", defaultValue = "1",
            description = "Simulated seconds per wall second (default ${DEFAULT-VALUE}).")
    double timeScale;

    @Option(names = "--repo",
            description = "The K-ICNP repository (holding robots-sim/); default: found from the working directory.")
    Path repo;

    @Option(names = "--for", paramLabel = "SECONDS",
            description = "Stop after this many seconds (default: run until interrupted).")
    Double duration;

    @Mixin
    TlsTrustOptions tls;

    @Spec
    CommandSpec spec;

    @Override public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        GatewayAddress address;
        try {
            address = GatewayAddress.parse(gateway);
        } catch (IllegalArgumentException e) {
            err.println(e.getMessage());
            return 2;
        }
        if (!(timeScale >= 0 && timeScale <= 1000)) {
            err.println("--time-scale " + timeScale + " is outside 0..1000.");
            return 2;
        }
        if (duration != null && !(duration > 0 && duration < Double.POSITIVE_INFINITY)) {
            err.println("--for " + duration + " is not a positive number of seconds.");
            return 2;
        }
        Properties tokenFile;
        try {
            tokenFile = AgentFile.read(tokens);
        } catch (IllegalArgumentException e) {
            err.println(e.getMessage());
            return 2;
        }
        Optional<SocketFactory> sockets;
        try {
            sockets = tls.socketFactory();
        } catch (IllegalArgumentException e) {
            err.println(e.getMessage());
            return 2;
        }
        for (String robot : ROBOTS) {
            if (tokenFile.getProperty(robot + ".token", "").isBlank()) {
                err.println("The tokens file '" + tokens + "' has no '" + robot + ".token'.");
                return 2;
            }
        }
        // Before the simulator starts: with no server there, the agents would only time out.
        try (java.net.Socket probe = new java.net.Socket()) {
            probe.connect(new java.net.InetSocketAddress(address.host(), address.port()), 2000);
        } catch (IOException e) {
            err.println("No server answers at " + gateway + " (" + (e.getMessage() == null ? e : e.getMessage())
                    + "); start one first (./kicnp serve KB_DIR) and give its agent file with --tokens.");
            return 1;
        }
        SimOptions options = SimOptions.defaults().withSeed(seed).withTimeScale(timeScale);
        if (repo != null) {
            options = options.withRepoRoot(repo);
        }
        // Completed by SIGTERM or Ctrl-C (the hook), or by the simulator's death.
        CompletableFuture<Void> stop = new CompletableFuture<>();
        CountDownLatch stopped = new CountDownLatch(1);
        List<RobotAgent> agents = new ArrayList<>();
        AtomicBoolean stopping = new AtomicBoolean();
        // Installed before anything starts: a SIGTERM during start-up must stop what has started so far too.
        Thread hook = stopHook(stop, stopped);
        Runtime.getRuntime().addShutdownHook(hook);
        try (SimWorld world = SimWorld.start(options)) {
            world.addListener(e -> {
                if (e instanceof SimEvent.Exited x && !stopping.get()) {
                    err.println("The simulator is gone: " + x.reason() + ".");
                    stop.complete(null);
                }
            });
            out.printf("Simulator started (pid %d, seed %d, time scale %s).%n", world.pid(), seed, timeScale);
            try {
                return runAgents(world, address, sockets, tokenFile, agents, stop, out);
            } finally {
                // The agents go first, so that closing the simulator is not reported to the server as its death.
                stopping.set(true);
                agents.reversed().forEach(RobotAgent::close);
            }
        } catch (SimulatorException | AgentException e) {
            err.println(e.getMessage());
            return 1;
        } finally {
            out.println("Robots stopped.");
            out.flush();
            stopped.countDown();
            try {
                Runtime.getRuntime().removeShutdownHook(hook);
            } catch (IllegalStateException e) {
                // Shutting down already: the hook is running.
            }
        }
    }

    /**
     * On SIGTERM or Ctrl-C the JVM halts once its hooks return: this one asks for a stop and waits until the agents
     * and the simulator have been stopped, so the agents leave the server cleanly and the simulator is shut down, not
     * cut off.
     */
    private static Thread stopHook(CompletableFuture<Void> stop, CountDownLatch stopped) {
        return new Thread(() -> {
            stop.complete(null);
            try {
                stopped.await(STOP_WAIT.toMillis(), TimeUnit.MILLISECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "kicnp-robots-stop");
    }

    private int runAgents(SimWorld world, GatewayAddress address, Optional<SocketFactory> sockets,
                          Properties tokenFile, List<RobotAgent> agents, CompletableFuture<Void> stop, PrintWriter out) {
        for (String robot : ROBOTS) {
            if (stop.isDone()) {
                return stoppedWith(world);
            }
            AgentOptions plain = AgentOptions.of(address.host(), address.port(), robot, AgentKind.ROBOT,
                    tokenFile.getProperty(robot + ".token").strip());
            AgentOptions ao = sockets.map(plain::withSocketFactory).orElse(plain);
            RobotAgent agent = switch (robot) {
                case "robovie" -> new RobovieAgent(ao, world);
                case "pino" -> new PinoAgent(ao, world);
                case "scout" -> new ScoutAgent(ao, world);
                default -> new AiboAgent(ao, world);
            };
            agents.add(agent);
            if (!startAndAwait(agent, stop)) {
                return stoppedWith(world);
            }
            out.printf("Agent '%s' registered with %s (%d capability frames).%n", robot, gateway,
                    agent.driver().capabilities().size());
        }
        out.flush();
        if (duration != null) {
            stop.copy().completeOnTimeout(null, (long) (duration * 1000), TimeUnit.MILLISECONDS).join();
        } else {
            stop.join();
        }
        return stop.isDone() ? stoppedWith(world) : 0;
    }

    /** The exit code after a stop was asked for: 1 when it was the simulator's death, 0 for SIGTERM or Ctrl-C. */
    private static int stoppedWith(SimWorld world) {
        return world.alive() ? 0 : 1;
    }

    /**
     * Starts the agent and waits until it is registered, or until a stop is asked for (false): a server slow to
     * answer must not hold a SIGTERM during start-up past the hook's wait, after which the JVM halts regardless.
     *
     * @throws AgentException when the agent is refused or not registered in time
     */
    private static boolean startAndAwait(RobotAgent agent, CompletableFuture<Void> stop) {
        CompletableFuture<Void> registered = CompletableFuture.runAsync(() -> agent.startAndAwait(REGISTER_WAIT),
                r -> Thread.ofVirtual().name("kicnp-robots-register-" + agent.name()).start(r));
        try {
            CompletableFuture.anyOf(registered, stop).join();
        } catch (CompletionException e) {
            throw e.getCause() instanceof RuntimeException cause ? cause : e;
        }
        return !stop.isDone();
    }
}
