package org.kicnp.inference;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import org.kicnp.core.ConditionParser;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

/** Builds small knowledge bases for engine tests, with a script host whose "scripts" are named Java functions. */
final class Fixture {
    final KnowledgeBase kb = KnowledgeBase.create();
    final Scripts scripts = new Scripts();
    final List<Action> sent = new ArrayList<>();
    /** What the engine asked the robots to stop: "actionId: reason". */
    final List<String> cancelled = new ArrayList<>();
    final List<TraceEvent> trace = new ArrayList<>();
    long now = 1_000;

    /** The paper's model: users, mouth, speech, the AskUserName and Greeting behavior frames. */
    static Fixture paper() {
        Fixture f = new Fixture();
        f.cls("System", null).cls("User", "System").cls("KnownUser", "User").cls("NewUser", "User")
                .cls("Robot", "System").cls("Mouth", "Robot").cls("Behaviors", null).cls("Speech", "Behaviors");
        f.kb.add(Frame.classFrame("AskUserName").parent("Speech")
                .slot(inst("mUser", "NewUser")).slot(inst("mMouth", "Mouth"))
                .slot(Slot.ofValue("onInstantiate", DataType.STRING, Value.of("ask-name"))).build());
        f.kb.add(Frame.classFrame("Greeting").parent("Speech")
                .slot(inst("mUser", "KnownUser")).slot(inst("mMouth", "Mouth"))
                .slot(Slot.ofValue("onInstantiate", DataType.STRING, Value.of("greet"))).build());
        f.scripts.define("ask-name", g -> call(g, "sendmsg", view(g).get("mMouth"), "What is your name?"));
        f.scripts.define("greet", g -> call(g, "Sendmsg", view(g).get("mMouth"),
                "Hi! Nice to meet you. Welcome to visit my room!"));
        return f;
    }

    Fixture cls(String name, String parent) {
        Frame.Builder b = Frame.classFrame(name);
        if (parent != null) {
            b.parent(parent);
        }
        kb.add(b.build());
        return this;
    }

    /** A required, shared, unique instance slot, as the paper's tables check them. */
    static Slot inst(String name, String argument) {
        return Slot.builder(name, DataType.INSTANCE).argument(argument).required(true).shared(true).unique(true)
                .build();
    }

    static Slot inst(String name, String argument, String condition) {
        return Slot.builder(name, DataType.INSTANCE).argument(argument).required(true).shared(true).unique(true)
                .condition(ConditionParser.parse(condition)).build();
    }

    static Slot str(String name, String value) {
        return Slot.ofValue(name, DataType.STRING, Value.of(value));
    }

    static Slot num(String name, long value) {
        return Slot.ofValue(name, DataType.INTEGER, Value.of(value));
    }

    /** Asserts a runtime instance with slot values (strings, numbers, or "@name" for references). */
    String assertFact(String name, String cls, Object... slotsAndValues) {
        Frame.Builder b = Frame.instance(name, cls).provenance(Provenance.RUNTIME);
        for (int i = 0; i < slotsAndValues.length; i += 2) {
            String slot = (String) slotsAndValues[i];
            Object v = slotsAndValues[i + 1];
            b.slot(switch (v) {
                case Long l -> num(slot, l);
                case Integer n -> num(slot, n);
                case String s when s.startsWith("@") -> Slot.builder(slot, kb.slot(cls, slot).map(e -> e.slot().type())
                        .orElse(DataType.FRAME)).value(Value.ref(s.substring(1))).build();
                default -> str(slot, v.toString());
            });
        }
        kb.add(b.build());
        return name;
    }

    InferenceEngine engine() {
        return engine(EngineOptions.defaults());
    }

    InferenceEngine engine(EngineOptions options) {
        InferenceEngine e = InferenceEngine.builder(kb).options(options).scripts(scripts).actionSink(new ActionSink() {
            @Override public void send(Action action) {
                sent.add(action);
            }

            @Override public void cancel(Action action, String reason) {
                cancelled.add(action.id() + ": " + reason);
            }
        }).clock(() -> now).build();
        e.addTraceListener(trace::add);
        return e;
    }

    List<String> instancesOf(String cls) {
        return kb.instancesOf(cls).stream().map(Frame::name).toList();
    }

    <T extends TraceEvent> List<T> traced(Class<T> type) {
        return trace.stream().filter(type::isInstance).map(type::cast).toList();
    }

    @SuppressWarnings("unchecked")
    static Map<String, Object> view(Map<String, Object> g) {
        return (Map<String, Object>) g.get("s");
    }

    static Object call(Map<String, Object> g, String fn, Object... args) {
        return ((HostFunction) g.get(fn)).call(List.of(args));
    }

    /** A script host whose sources name Java functions of the globals; counts the calls of each. */
    static final class Scripts implements ScriptHost {
        final Map<String, Function<Map<String, Object>, Object>> bodies = new HashMap<>();
        final Map<String, Integer> calls = new HashMap<>();

        void define(String source, Function<Map<String, Object>, Object> body) {
            bodies.put(source, body);
        }

        int calls(String source) {
            return calls.getOrDefault(source, 0);
        }

        @Override public Object run(String frame, String slot, String source, Map<String, Object> globals) {
            calls.merge(source, 1, Integer::sum);
            Function<Map<String, Object>, Object> body = bodies.get(source.strip());
            if (body == null) {
                throw new IllegalStateException("No test script named '" + source + "'.");
            }
            return body.apply(globals);
        }

        @Override public boolean test(String frame, String slot, String source, Map<String, Object> globals) {
            return Boolean.TRUE.equals(run(frame, slot, source, globals));
        }
    }
}
