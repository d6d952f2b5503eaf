package org.kicnp.cli;

import java.io.PrintWriter;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.kicnp.agent.ActionFailedException;
import org.kicnp.agent.AgentTimeoutException;
import org.kicnp.agent.CommandTicket;
import org.kicnp.cli.AgentCommand.CliAgent;
import org.kicnp.cli.AgentCommand.Hooks;
import org.kicnp.cli.AgentCommand.Subcommand;
import org.kicnp.protocol.Message;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;

import static org.kicnp.cli.AgentCommand.pairs;
import static org.kicnp.cli.AgentCommand.requireAgentName;
import static org.kicnp.cli.AgentCommand.requirePositive;

/**
 * The subcommands of {@code kicnp agent} that drive a robot's action through its life cycle: {@code command} sends one
 * and follows its feedback to the end (cancelling it on Ctrl-C or when {@code --wait} runs out), {@code cancel} stops
 * one in flight.
 */
final class AgentActions {
    private AgentActions() {
    }

    @Command(name = "command", mixinStandardHelpOptions = true,
            description = "Send a robot a command and print its feedback as JSON lines as it comes, until it ends "
                    + "(exit 0) or fails (exit 1). Ctrl-C, or no end within --wait, cancels it. Arguments are "
                    + "NAME=VALUE.")
    static final class Order extends Subcommand {

        @Parameters(index = "0", paramLabel = "ROBOT", description = "The robot's agent.")
        String robot;

        @Parameters(index = "1", paramLabel = "ACTION", description = "The action.")
        String action;

        @Parameters(index = "2..*", paramLabel = "NAME=VALUE", description = "The action's arguments.")
        List<String> args = new ArrayList<>();

        @Option(names = "--wait", defaultValue = "60", paramLabel = "SECONDS",
                description = "How long to wait for the action to end before cancelling it (default "
                        + "${DEFAULT-VALUE}).")
        double waitSeconds;

        /** The feedback printed so far: the waiting loop and a Ctrl-C's cancel print each line once between them. */
        private final Printed printed = new Printed();

        @Override public Integer call() throws InterruptedException {
            requireAgentName(spec, "ROBOT", robot);
            if (action.isBlank()) {
                throw new ParameterException(spec.commandLine(), "ACTION is empty; name the action to send to '"
                        + robot + "'.");
            }
            requirePositive(spec, "--wait", waitSeconds);
            Map<String, String> named = pairs(spec, args);
            PrintWriter out = spec.commandLine().getOut();
            PrintWriter err = spec.commandLine().getErr();
            long deadline = System.nanoTime() + Math.round(waitSeconds * 1e9);
            try (CliAgent a = connect(Hooks.NONE)) {
                CommandTicket t = a.command(robot, action, named);
                err.println("Command '" + t.command().id() + "' sent to '" + robot + "'; Ctrl-C cancels it.");
                err.flush();
                // Ctrl-C while it runs cancels it, as a goal is cancelled in ROS, and shows how it ended.
                Thread onInterrupt = new Thread(() -> cancelAndReport(a, t, "interrupted at the terminal", out),
                        "kicnp-agent-cancel");
                Runtime.getRuntime().addShutdownHook(onInterrupt);
                try {
                    while (true) {
                        try {
                            t.result(Duration.ofMillis(100));
                            printed.upTo(t, out);
                            return 0;
                        } catch (ActionFailedException e) {
                            printed.upTo(t, out);
                            return 1;
                        } catch (AgentTimeoutException e) {
                            printed.upTo(t, out);
                            if (System.nanoTime() > deadline) {
                                err.println("kicnp agent command: '" + t.command().id() + "' did not end within "
                                        + waitSeconds + " s; cancelling it.");
                                cancelAndReport(a, t, "the command line stopped waiting after " + waitSeconds + " s",
                                        out);
                                return 1;
                            }
                        }
                    }
                } finally {
                    try {
                        Runtime.getRuntime().removeShutdownHook(onInterrupt);
                    } catch (IllegalStateException shuttingDown) {
                        // The hook is running: it cancels and reports.
                    }
                }
            }
        }

        /** Cancels the command unless it ended, then prints its feedback up to the end (waiting up to 5 s for it). */
        private void cancelAndReport(CliAgent a, CommandTicket t, String reason, PrintWriter out) {
            try {
                a.cancel(robot, t.command().id(), reason);
                t.result(Duration.ofSeconds(5));
            } catch (RuntimeException ended) {
                // Ended or failed meanwhile, refused because it is no longer in flight, or no answer in time.
            }
            printed.upTo(t, out);
        }
    }

    /** Prints a command's feedback as JSON lines, each once. */
    static final class Printed {
        private int count;

        synchronized void upTo(CommandTicket t, PrintWriter out) {
            List<Message.Feedback> all = t.feedback();
            for (; count < all.size(); count++) {
                out.println(AgentJson.feedback(all.get(count)));
            }
            out.flush();
        }
    }

    @Command(name = "cancel", mixinStandardHelpOptions = true,
            description = "Ask a robot to stop a command in flight (any user agent may, whoever sent it); the command "
                    + "then ends with feedback 'failed: cancelled: …' to whoever sent it.")
    static final class Cancel extends Subcommand {

        @Parameters(index = "0", paramLabel = "ROBOT", description = "The robot's agent.")
        String robot;

        @Parameters(index = "1", paramLabel = "COMMAND_ID", description = "The command's id.")
        String command;

        @Option(names = "--reason", defaultValue = "cancelled from the command line", paramLabel = "TEXT",
                description = "Why (default: ${DEFAULT-VALUE}).")
        String reason;

        @Override public Integer call() {
            requireAgentName(spec, "ROBOT", robot);
            try (CliAgent a = connect(Hooks.NONE)) {
                a.cancel(robot, command, reason);
            }
            spec.commandLine().getOut().println("Asked '" + robot + "' to stop '" + command + "'.");
            return 0;
        }
    }
}
