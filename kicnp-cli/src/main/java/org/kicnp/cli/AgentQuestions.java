package org.kicnp.cli;

import static org.kicnp.cli.AgentCommand.pairs;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.kicnp.cli.AgentCommand.CliAgent;
import org.kicnp.cli.AgentCommand.Hooks;
import org.kicnp.cli.AgentCommand.Subcommand;
import org.kicnp.core.Frame;
import org.kicnp.protocol.FrameText;
import org.kicnp.protocol.Message;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

/**
 * The subcommands of {@code kicnp agent} that ask the server's knowledge base and change nothing: {@code query},
 * {@code ask}, {@code prove}, {@code why} and {@code why-not}. Kept apart from the commands that change knowledge or
 * talk to other agents because they share a shape — connect, ask once, print the answer (XML or JSON on stdout, a
 * count or summary on stderr) — and can be run against a live server at any time without side effects.
 */
final class AgentQuestions {
    private AgentQuestions() {
    }

    @Command(name = "query", mixinStandardHelpOptions = true,
            description = "Print every instance of a class (and of the classes below it) as one document in the "
                    + "paper's "
                    + "XML.")
    static final class Query extends Subcommand {

        @Parameters(paramLabel = "CLASS", description = "The class.")
        String ofClass;

        @Override public Integer call() {
            List<Frame> frames;
            try (CliAgent a = connect(Hooks.NONE)) {
                frames = a.query(ofClass);
            }
            PrintWriter out = spec.commandLine().getOut();
            out.print(FrameText.document(frames)); // one document, which `agent assert` takes back as it is
            out.flush();
            spec.commandLine().getErr().println(frames.size() + " instance" + (frames.size() == 1 ? "" : "s")
                    + " of '" + ofClass + "'.");
            return 0;
        }
    }

    @Command(name = "ask", mixinStandardHelpOptions = true,
            description = "Print the effective value of a slot (inherited along IS-A); exit 1 when it has none.")
    static final class Ask extends Subcommand {

        @Parameters(index = "0", paramLabel = "FRAME", description = "The frame.")
        String frame;

        @Parameters(index = "1", paramLabel = "SLOT", description = "The slot.")
        String slot;

        @Override public Integer call() {
            Optional<org.kicnp.core.Value> v;
            try (CliAgent a = connect(Hooks.NONE)) {
                v = a.ask(frame, slot);
            }
            if (v.isEmpty()) {
                spec.commandLine().getErr().println("kicnp agent ask: '" + frame + "' has no value in slot '" + slot
                        + "'.");
                return 1;
            }
            spec.commandLine().getOut().println(v.get().text());
            return 0;
        }
    }

    @Command(name = "prove", mixinStandardHelpOptions = true,
            description = "Backward chaining on the server: every instance of the class that exists or could be "
                    + "derived from what exists (slots fixed by SLOT=INSTANCE), each with its proof, as one JSON "
                    + "array: {ofClass, instance (when it exists), slots: {slot: proof}, assumptions (the script "
                    + "conditions of a binding that holds an instance still to be derived; those of existing "
                    + "instances are run)}. Nothing is created.")
    static final class Prove extends Subcommand {

        @Parameters(index = "0", paramLabel = "CLASS", description = "The class.")
        String ofClass;

        @Parameters(index = "1..*", paramLabel = "SLOT=INSTANCE", description = "Slots the answers must hold.")
        List<String> bindings = new ArrayList<>();

        @Override public Integer call() {
            Map<String, String> fixed = pairs(spec, bindings);
            List<Message.ProofNode> proofs;
            try (CliAgent a = connect(Hooks.NONE)) {
                proofs = a.prove(ofClass, fixed);
            }
            spec.commandLine().getOut().println(AgentJson.pretty(proofs.stream().map(AgentJson::proof).toList()));
            spec.commandLine().getErr().println(proofs.size() + " answer" + (proofs.size() == 1 ? "" : "s") + ".");
            return 0;
        }
    }

    @Command(name = "why", mixinStandardHelpOptions = true,
            description = "Why an instance exists, back to the stimuli, as one JSON object: {instance, ofClass, "
                    + "derived, binding, conditions, supports: [...]}.")
    static final class Why extends Subcommand {

        @Parameters(paramLabel = "INSTANCE", description = "The instance.")
        String instance;

        @Override public Integer call() {
            Message.Reason reason;
            try (CliAgent a = connect(Hooks.NONE)) {
                reason = a.why(instance);
            }
            spec.commandLine().getOut().println(AgentJson.pretty(AgentJson.reason(reason)));
            return 0;
        }
    }

    @Command(name = "why-not", mixinStandardHelpOptions = true,
            description = "Why a behavior frame has not fired, as one JSON object: {frame, summary, slots: [{slot, "
                    + "argument, condition, candidates, rejected, candidateCount, rejectedCount}], bindings: [{binding, "
                    + "outcome, reason}], truncated}; the summary also on stderr. Nothing is created (script "
                    + "conditions run, as on matching, and change nothing).")
    static final class WhyNot extends Subcommand {

        @Parameters(index = "0", paramLabel = "FRAME", description = "The behavior frame.")
        String frame;

        @Parameters(index = "1..*", paramLabel = "SLOT=INSTANCE", description = "Required slots to hold fixed.")
        List<String> bindings = new ArrayList<>();

        @Override public Integer call() {
            Map<String, String> fixed = pairs(spec, bindings);
            Message.NotFired answer;
            try (CliAgent a = connect(Hooks.NONE)) {
                answer = a.whyNot(frame, fixed);
            }
            spec.commandLine().getOut().println(AgentJson.pretty(AgentJson.notFired(answer)));
            spec.commandLine().getErr().println(answer.summary());
            return 0;
        }
    }
}
