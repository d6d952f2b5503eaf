package org.kicnp.cli;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Callable;
import org.kicnp.core.Change;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.KnowledgeException;
import org.kicnp.core.Provenance;
import org.kicnp.core.xml.KnowledgeLoader;
import org.kicnp.core.xml.KnowledgeXmlException;
import org.kicnp.core.xml.SourcedFrame;
import org.kicnp.inference.Action;
import org.kicnp.inference.Answer;
import org.kicnp.inference.EngineOptions;
import org.kicnp.inference.GraalScriptHost;
import org.kicnp.inference.InferenceEngine;
import org.kicnp.inference.InferenceException;
import org.kicnp.inference.TraceEvent;
import org.kicnp.inference.WhyNot;
import org.kicnp.script.ScriptConfig;
import org.kicnp.script.ScriptRuntime;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code kicnp infer}: loads a knowledge base, asserts instance frames as stimuli, runs the inference engine to
 * quiescence and prints the instances it created and the actions it issued (to a recording sink: no robot is
 * contacted), optionally the trace as JSON lines, the answers to questions asked by backward chaining, and why
 * behavior frames did not fire.
 */
@Command(name = "infer", mixinStandardHelpOptions = true,
        customSynopsis = {"kicnp infer [-hV] KB... [--assert=FILE_OR_XML...]... [--ask=CLASS]...",
            "                   [--why-not=FRAME]... [--expect=CLASS[=N]]... [--expect-none=CLASS]...",
            "                   [--expect-action=[ROBOT:]ACTION]... [--trace] [--max-firings=N]",
            "                   [--max-depth=N]"},
        description = "Run the inference engine on a knowledge base with asserted instances and print what it did. "
                + "With --expect options it is a test of the knowledge base's rules, for scripts and CI: each "
                + "expectation is checked after the run and printed as pass or FAIL, a failed one on a behavior "
                + "frame with why it did not fire.",
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {
            "0:done, every expectation met",
            "1:the knowledge base or an asserted file could not be used, or the run failed",
            "2:wrong usage",
            "3:an expectation was not met"
        })
public final class InferCommand implements Callable<Integer> {
    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    // Not required at parse time: "--assert X KB" makes --assert take KB too, and picocli would only say that KB is
    // missing; call() says what happened instead.
    @Parameters(arity = "0..*", paramLabel = "KB", description = "Knowledge base XML files or directories (required; give them before --assert, which "
                    + "takes every value after it).")
    List<Path> knowledge = new ArrayList<>();

    @Option(names = "--assert", arity = "1..*", paramLabel = "FILE_OR_XML",
            description = "Instance frames to assert: an XML file, or XML text starting with '<'.")
    List<String> asserts = new ArrayList<>();

    @Option(names = "--trace", description = "Print every inference step as a JSON line.")
    boolean trace;

    @Option(names = "--ask", paramLabel = "CLASS", description = "After the run, ask for every instance of the class.")
    List<String> asks = new ArrayList<>();

    @Option(names = "--why-not", paramLabel = "FRAME", description = "After the run, say why the behavior frame did "
            + "not fire: each required slot's candidates, and what stops each binding of them.")
    List<String> whyNots = new ArrayList<>();

    @Option(names = "--expect", paramLabel = "CLASS[=N]", description = "After the run, expect an instance of "
            + "CLASS (or of a class below it) in the knowledge base; with =N, exactly N of them.")
    List<String> expects = new ArrayList<>();

    @Option(names = "--expect-none", paramLabel = "CLASS", description = "After the run, expect no instance of "
            + "CLASS (or of a class below it).")
    List<String> expectNone = new ArrayList<>();

    @Option(names = "--expect-action", paramLabel = "[ROBOT:]ACTION", description = "Expect the run to have issued "
            + "the action ACTION (to ROBOT, when given).")
    List<String> expectActions = new ArrayList<>();

    @Option(names = "--max-firings", paramLabel = "N", description = "Firings allowed per run (default: ${DEFAULT-VALUE}).")
    int maxFirings = EngineOptions.defaults().maxFirings();

    @Option(names = "--max-depth", paramLabel = "N", description = "How deep derived instances may rest on one "
            + "another, each made from the one before (default: ${DEFAULT-VALUE}); a deeper one stops the run as a "
            + "knowledge base that feeds itself.")
    int maxDepth = EngineOptions.defaults().maxDerivationDepth();

    @Override public Integer call() {
        if (knowledge.isEmpty()) {
            throw new CommandLine.ParameterException(spec.commandLine(), "Missing the knowledge base (KB)"
                    + (asserts.isEmpty() ? "." : ": --assert takes every value after it up to the next option, "
                    + String.join(" ", asserts) + " here. Give the knowledge base first: kicnp infer KB --assert "
                    + "FILE_OR_XML..."));
        }
        if (asserts.stream().anyMatch(String::isBlank)) {
            // Taken as a path, an empty value would be the working directory, and every file in it asserted.
            throw new CommandLine.ParameterException(spec.commandLine(), "--assert got an empty value; give an XML "
                    + "file or XML text starting with '<'.");
        }
        if (maxFirings < 1) {
            throw new CommandLine.ParameterException(spec.commandLine(),
                    "--max-firings must be at least 1, not " + maxFirings + ".");
        }
        if (maxDepth < 1) {
            throw new CommandLine.ParameterException(spec.commandLine(),
                    "--max-depth must be at least 1, not " + maxDepth + ".");
        }
        List<Expectation> expectations = expectations();
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        try (ScriptRuntime runtime = ScriptRuntime.create(ScriptConfig.defaults())) {
            List<Path> files = KnowledgeLoader.expand(knowledge);
            if (files.isEmpty()) {
                // As validate says: an empty knowledge base would infer nothing and look like a quiet success.
                err.println("infer: no knowledge files (*.xml) found in " + knowledge + ".");
                err.flush();
                return 1;
            }
            KnowledgeBase kb = KnowledgeBase.create();
            List<SourcedFrame> declared;
            try {
                declared = KnowledgeLoader.parse(files, kb);
            } catch (KnowledgeXmlException e) {
                // The load below fails too, and reports these errors with the frame-model problems of the others.
                declared = e.framesRead();
            }
            if (declared.stream().noneMatch(s -> s.frame().name().equals(InferenceEngine.FEEDBACK_CLASS))) {
                kb.add(InferenceEngine.feedbackClass());
            }
            KnowledgeLoader.load(kb, files);
            List<Action> sent = new ArrayList<>();
            Map<String, String> created = new LinkedHashMap<>();
            InferenceEngine engine = InferenceEngine.builder(kb).options(EngineOptions.defaults()
                            .withMaxFirings(maxFirings).withMaxDerivationDepth(maxDepth))
                    .scripts(new GraalScriptHost(runtime)).actionSink(sent::add).build();
            ObjectMapper json = new ObjectMapper();
            engine.addTraceListener(e -> {
                if (e instanceof TraceEvent.Fired f) {
                    created.put(f.instance(), f.frame());
                } else if (e instanceof TraceEvent.Retracted r) {
                    created.remove(r.instance());
                }
                if (trace) {
                    ObjectNode node = json.createObjectNode().put("event", e.kind());
                    node.setAll((ObjectNode) json.valueToTree(e));
                    out.println(node);
                }
            });
            engine.runToQuiescence();
            for (String a : asserts) {
                assertInstances(kb, a);
                engine.runToQuiescence();
            }
            // Every question is answered before anything is printed, so a class that is not there fails the
            // command without leaving half its report (an "Answers for" heading with nothing under it) on stdout.
            Map<String, List<Answer>> answers = new LinkedHashMap<>();
            for (String cls : asks) {
                Frame asked = kb.frame(cls).orElseThrow(() -> new IllegalArgumentException("--ask names '" + cls
                        + "', which is not a frame of the knowledge base."));
                if (asked.isInstance()) {
                    throw new IllegalArgumentException("--ask takes a class, but '" + cls + "' is an instance.");
                }
                answers.put(cls, engine.ask(cls, Map.of()));
            }
            List<WhyNot> diagnoses = new ArrayList<>();
            for (String frame : whyNots) {
                if (!kb.contains(frame)) {
                    throw new IllegalArgumentException("--why-not names '" + frame
                            + "', which is not a frame of the knowledge base.");
                }
                diagnoses.add(engine.whyNot(frame, Map.of()));
            }
            print(out, kb, created, sent);
            answers.forEach((cls, list) -> {
                out.println("Answers for " + cls + ":");
                for (Answer a : list) {
                    out.println("  " + a.instance().orElse("(derivable " + a.className() + ")") + " " + a.slots());
                }
            });
            diagnoses.forEach(w -> printWhyNot(out, w));
            boolean met = check(out, kb, engine, sent, expectations);
            out.flush();
            return met ? 0 : 3;
        } catch (KnowledgeException | InferenceException | IllegalArgumentException e) {
            err.println("infer: " + e.getMessage());
            err.flush();
            return 1;
        } catch (RuntimeException e) {
            err.println("infer: " + e.getClass().getSimpleName() + ": " + e.getMessage());
            err.flush();
            return 1;
        }
    }

    /** One {@code --expect…} option, read. {@code count} is -1 for "at least one". */
    private record Expectation(String option, String cls, int count, String robot, String action) {
    }

    private List<Expectation> expectations() {
        List<Expectation> out = new ArrayList<>();
        for (String e : expects) {
            int eq = e.lastIndexOf('=');
            String cls = eq < 0 ? e : e.substring(0, eq);
            int count = -1;
            if (eq >= 0) {
                try {
                    count = Integer.parseInt(e.substring(eq + 1));
                } catch (NumberFormatException x) {
                    count = -2;
                }
            }
            if (cls.isBlank() || count < -1) {
                throw new CommandLine.ParameterException(spec.commandLine(), "--expect '" + e + "' is not CLASS or "
                        + "CLASS=N with N a whole number from 0.");
            }
            out.add(new Expectation("--expect", cls, count, null, null));
        }
        for (String cls : expectNone) {
            if (cls.isBlank()) {
                throw new CommandLine.ParameterException(spec.commandLine(), "--expect-none got an empty class name.");
            }
            out.add(new Expectation("--expect-none", cls, 0, null, null));
        }
        for (String a : expectActions) {
            int colon = a.indexOf(':');
            String robot = colon < 0 ? null : a.substring(0, colon);
            String action = colon < 0 ? a : a.substring(colon + 1);
            if (action.isBlank() || robot != null && robot.isBlank()) {
                throw new CommandLine.ParameterException(spec.commandLine(), "--expect-action '" + a + "' is not "
                        + "ACTION or ROBOT:ACTION.");
            }
            out.add(new Expectation("--expect-action", null, -1, robot, action));
        }
        return out;
    }

    /** Checks and prints every expectation; true when all are met. */
    private static boolean check(PrintWriter out, KnowledgeBase kb, InferenceEngine engine, List<Action> sent,
                                 List<Expectation> expectations) {
        if (expectations.isEmpty()) {
            return true;
        }
        // Every class named must be one, before anything is judged: a misspelt class would pass --expect-none.
        for (Expectation e : expectations) {
            if (e.cls() != null) {
                Frame f = kb.frame(e.cls()).orElseThrow(() -> new IllegalArgumentException(e.option() + " names '"
                        + e.cls() + "', which is not a frame of the knowledge base."));
                if (f.isInstance()) {
                    throw new IllegalArgumentException(e.option() + " takes a class, but '" + e.cls()
                            + "' is an instance.");
                }
            }
        }
        out.println("Expectations:");
        int failed = 0;
        for (Expectation e : expectations) {
            boolean ok;
            String what;
            if (e.cls() != null) {
                List<String> found = kb.instancesOf(e.cls()).stream().map(Frame::name).toList();
                ok = e.count() < 0 ? !found.isEmpty() : found.size() == e.count();
                String wanted = e.count() < 0 ? "an instance of " + e.cls()
                        : e.count() == 0 ? "no instance of " + e.cls()
                        : e.count() + " instance" + (e.count() == 1 ? "" : "s") + " of " + e.cls();
                what = wanted + ": " + (found.isEmpty() ? "none" : found.size() + " (" + abbreviate(String.join(", ",
                        found)) + ")");
                out.println("  " + (ok ? "pass" : "FAIL") + "  " + what);
                if (!ok && found.isEmpty()) {
                    whyNotSummary(engine, e.cls()).ifPresent(w -> out.println("        why not: " + w));
                }
            } else {
                List<Action> matching = sent.stream().filter(a -> a.name().equals(e.action())
                        && (e.robot() == null || a.robot().equals(e.robot()))).toList();
                ok = !matching.isEmpty();
                what = "action " + (e.robot() == null ? "" : e.robot() + ":") + e.action() + ": "
                        + (ok ? matching.size() + " issued (" + matching.getFirst().id() + " by "
                        + matching.getFirst().instance() + ")" : "not issued (issued: " + (sent.isEmpty() ? "none"
                        : abbreviate(String.join(", ", sent.stream().map(a -> a.robot() + ":" + a.name())
                        .toList()))) + ")");
                out.println("  " + (ok ? "pass" : "FAIL") + "  " + what);
            }
            if (!ok) {
                failed++;
            }
        }
        out.println(failed == 0 ? "All " + expectations.size() + " expectations met."
                : failed + " of " + expectations.size() + " expectations not met.");
        return failed == 0;
    }

    /** Why a behavior frame did not fire, in one sentence; empty for a class that is not a behavior frame. */
    private static Optional<String> whyNotSummary(InferenceEngine engine, String frame) {
        try {
            return Optional.of(engine.whyNot(frame, Map.of()).summary());
        } catch (IllegalArgumentException notABehaviorFrame) {
            return Optional.empty();
        }
    }

    private static void assertInstances(KnowledgeBase kb, String source) {
        List<SourcedFrame> frames = source.stripLeading().startsWith("<")
                ? KnowledgeLoader.parseText(source, "--assert", kb)
                : KnowledgeLoader.parse(List.of(Path.of(source)), kb);
        if (frames.isEmpty()) {
            // As the editor's import says: asserting nothing would run the engine on no stimulus and look like a
            // quiet success.
            throw new IllegalArgumentException("--assert " + abbreviate(source.strip())
                    + " holds no FRAME element; nothing was asserted.");
        }
        List<Change> adds = new ArrayList<>();
        for (SourcedFrame s : frames) {
            Frame f = s.frame();
            if (!f.isInstance()) {
                throw new IllegalArgumentException("--assert takes instance frames, but '" + f.name() + "' ("
                        + s.location() + ") is a class.");
            }
            adds.add(new Change.Add(f.toBuilder().provenance(Provenance.RUNTIME).build()));
        }
        kb.apply(adds);
    }

    private static String abbreviate(String text) {
        return text.length() <= 60 ? text : text.substring(0, 57) + "...";
    }

    private static void printWhyNot(PrintWriter out, WhyNot w) {
        out.println("Why not " + w.frame() + ": " + w.summary());
        for (WhyNot.SlotCandidates s : w.slots()) {
            out.println("  slot " + s.slot() + " (" + s.argument() + ", " + s.condition() + "): "
                    + (s.candidates().isEmpty() ? "no candidate" : String.join(" ", s.candidates()))
                    + more(s.candidateCount(), s.candidates().size()));
            s.rejected().forEach(r -> out.println("    turned away: " + r));
            if (s.rejectedCount() > s.rejected().size()) {
                out.println("    turned away:" + more(s.rejectedCount(), s.rejected().size()));
            }
        }
        for (WhyNot.Verdict v : w.bindings()) {
            StringBuilder sb = new StringBuilder("  ");
            v.binding().forEach((slot, fact) -> sb.append(slot).append('=').append(fact).append(' '));
            out.println(sb.append("-> ").append(v.outcome().phrase()).append(": ").append(v.reason()));
        }
    }

    /** " … and N more" when a list was cut at the engine's answer limit, else "". */
    private static String more(int count, int listed) {
        return count > listed ? " … and " + (count - listed) + " more" : "";
    }

    private static void print(PrintWriter out, KnowledgeBase kb, Map<String, String> created, List<Action> sent) {
        out.println("Created " + created.size() + " instance" + (created.size() == 1 ? "" : "s") + ":");
        created.forEach((name, frame) -> {
            StringBuilder sb = new StringBuilder("  ").append(name).append(" (").append(frame).append(")");
            kb.frame(name).ifPresent(f -> f.slots().forEach(s -> s.value().ifPresent(v ->
                    sb.append(' ').append(s.name()).append('=').append(v.text()))));
            out.println(sb);
        });
        out.println("Issued " + sent.size() + " action" + (sent.size() == 1 ? "" : "s") + ":");
        for (Action a : sent) {
            String via = a.target().equals(a.robot()) ? "" : " (via " + a.target() + ")";
            out.println("  " + a.id() + " " + a.robot() + via + " " + a.name() + " " + a.args() + " by " + a.instance());
        }
    }
}
