package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowable;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.kicnp.core.xml.KnowledgeLoader;
import org.kicnp.script.ScriptConfig;
import org.kicnp.script.ScriptRuntime;

/**
 * Runs the scenario files in {@code src/test/resources/scenarios}: each is a knowledge base in the paper's XML with
 * its steps and expectations in the first comment, one per line:
 * <pre>
 * assert NAME CLASS [slot=value | slot=@instance ...]   add a stimulus
 * change NAME slot=value ...                            replace slot values of an instance
 * destroy NAME                                          engine.destroy
 * run                                                   run to quiescence
 * end ACTION_NO result | fail ACTION_NO reason | start ACTION_NO | tick MILLIS
 * expect count CLASS N                                  number of instances of CLASS
 * expect fired FRAME:slot=inst ...                      the firings since the last expect fired, in order
 * expect action ROBOT NAME [ARG]                        an action was sent (ARG matched on the first argument)
 * expect actions N                                      number of actions sent so far
 * expect status ACTION_NO STATUS                        the state of the n-th action issued (1-based)
 * expect error TEXT                                     the next run fails with a message containing TEXT
 * expect why INSTANCE_OF_CLASS STIMULUS ...             the stimuli behind the (only) instance of a class
 * expect ask CLASS N                                    number of answers of backward chaining
 * </pre>
 */
class ScenarioTest {
    private static final Path DIR = Path.of("src", "test", "resources", "scenarios");
    private static final Pattern STEPS = Pattern.compile("<!--\\s*scenario:(.*?)-->", Pattern.DOTALL);
    private static ScriptRuntime runtime;

    @BeforeAll
    static void start() {
        runtime = ScriptRuntime.create(ScriptConfig.defaults().withTimeLimit(Duration.ofMillis(500)));
    }

    @AfterAll
    static void stop() {
        runtime.close();
    }

    static Stream<Path> scenarios() throws IOException {
        try (Stream<Path> files = Files.list(DIR)) {
            return files.filter(p -> p.toString().endsWith(".xml")).sorted().toList().stream();
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenarios")
    void scenario(Path file) throws IOException {
        String text = Files.readString(file);
        Matcher m = STEPS.matcher(text);
        assertThat(m.find()).as("%s has a scenario comment", file).isTrue();
        KnowledgeBase kb = KnowledgeBase.create();
        kb.add(InferenceEngine.feedbackClass());
        KnowledgeLoader.load(kb, List.of(file));
        long[] now = {1_000};
        List<Action> sent = new ArrayList<>();
        List<TraceEvent.Fired> fired = new ArrayList<>();
        InferenceEngine e = InferenceEngine.builder(kb).scripts(new GraalScriptHost(runtime)).actionSink(sent::add)
                .clock(() -> now[0]).options(EngineOptions.defaults().withMaxFirings(200)
                        .withActionTimeout(Duration.ofSeconds(10))).build();
        e.addTraceListener(t -> {
            if (t instanceof TraceEvent.Fired f) {
                fired.add(f);
            }
        });
        String expectError = null;
        int lineNo = 0;
        for (String raw : m.group(1).split("\n")) {
            lineNo++;
            String line = raw.strip();
            if (line.isEmpty() || line.startsWith("#") || lineNo == 1) {
                continue;
            }
            String[] w = line.split("\\s+");
            String where = file.getFileName() + ": " + line;
            switch (w[0]) {
                case "assert" -> kb.add(instance(kb, w[1], w[2], rest(w, 3)));
                case "change" -> {
                    Frame f = kb.require(w[1]);
                    Frame.Builder b = f.toBuilder();
                    slots(kb, f.parent().orElseThrow(), rest(w, 2)).forEach(b::slot);
                    kb.replace(b.build());
                }
                case "destroy" -> e.destroy(w[1]);
                case "start" -> e.actionStarted(e.actions().get(Integer.parseInt(w[1]) - 1).id());
                case "end" -> e.actionEnded(e.actions().get(Integer.parseInt(w[1]) - 1).id(), w[2]);
                case "fail" -> e.actionFailed(e.actions().get(Integer.parseInt(w[1]) - 1).id(), w[2]);
                case "tick" -> now[0] += Long.parseLong(w[1]);
                case "run" -> {
                    Throwable t = catchThrowable(e::runToQuiescence);
                    if (expectError != null) {
                        assertThat(t).as(where).isNotNull();
                        assertThat(t.getMessage()).as(where).contains(expectError);
                        expectError = null;
                    } else {
                        assertThat(t).as(where).isNull();
                    }
                }
                case "expect" -> {
                    switch (w[1]) {
                        case "count" -> assertThat(kb.countInstancesOf(w[2])).as(where).isEqualTo(Integer.parseInt(w[3]));
                        case "fired" -> {
                            List<String> got = fired.stream().map(f -> f.frame() + bindingText(f.binding())).toList();
                            fired.clear();
                            assertThat(got).as(where).containsExactly(rest(w, 2).toArray(String[]::new));
                        }
                        case "action" -> assertThat(sent).as(where).anySatisfy(a -> {
                            assertThat(a.robot()).isEqualTo(w[2]);
                            assertThat(a.name()).isEqualTo(w[3]);
                            if (w.length > 4) {
                                assertThat(a.args().getFirst()).startsWith(line.split("\\s+", 5)[4]);
                            }
                        });
                        case "actions" -> assertThat(sent).as(where).hasSize(Integer.parseInt(w[2]));
                        case "status" -> assertThat(e.actionStatus(e.actions().get(Integer.parseInt(w[2]) - 1).id()))
                                .as(where).contains(Action.Status.valueOf(w[3]));
                        case "error" -> expectError = line.split("\\s+", 3)[2];
                        case "why" -> assertThat(e.why(kb.instancesOf(w[2]).getFirst().name()).stimuli()).as(where)
                                .containsExactlyInAnyOrder(rest(w, 3).toArray(String[]::new));
                        case "ask" -> assertThat(e.ask(w[2], Map.of())).as(where).hasSize(Integer.parseInt(w[3]));
                        default -> throw new IllegalArgumentException("Unknown expectation in " + where);
                    }
                }
                default -> throw new IllegalArgumentException("Unknown step in " + where);
            }
        }
    }

    private static String bindingText(Map<String, String> binding) {
        return binding.entrySet().stream().sorted(Map.Entry.comparingByKey())
                .map(x -> ":" + x.getKey() + "=" + x.getValue()).reduce("", String::concat);
    }

    private static List<String> rest(String[] w, int from) {
        return List.of(w).subList(Math.min(from, w.length), w.length);
    }

    private static Frame instance(KnowledgeBase kb, String name, String cls, List<String> slotTexts) {
        Frame.Builder b = Frame.instance(name, cls).provenance(Provenance.RUNTIME);
        slots(kb, cls, slotTexts).forEach(b::slot);
        return b.build();
    }

    private static List<Slot> slots(KnowledgeBase kb, String cls, List<String> slotTexts) {
        List<Slot> out = new ArrayList<>();
        for (String s : slotTexts) {
            String[] kv = s.split("=", 2);
            DataType type = kb.slot(cls, kv[0]).map(x -> x.slot().type()).orElse(DataType.STRING);
            Value v = kv[1].startsWith("@") ? Value.ref(kv[1].substring(1)) : Value.parse(type, kv[1]);
            out.add(Slot.ofValue(kv[0], v instanceof Value.Ref && type == DataType.STRING ? DataType.FRAME : type, v));
        }
        return out;
    }
}
