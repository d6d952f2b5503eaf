package org.kicnp.inference;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Supplier;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The globals a behavior script sees: {@code s} (the instance's slots, read-only), {@code sendmsg}/{@code Sendmsg},
 * {@code command}, {@code create}, {@code destroy}, {@code cancel}, {@code actions}, {@code ask}, {@code log},
 * {@code frameName}, {@code frameExists} and {@code learn}. Every function that changes something only records an
 * {@link Effect}; the engine applies them after the script succeeds ({@code actions} and {@code ask} read the state
 * the script started in; {@code frameExists} does not see a {@code learn} of the same script).
 */
final class ScriptApi {
    private static final Logger LOG = LoggerFactory.getLogger(ScriptApi.class);

    /** The engine services the functions need. */
    interface Services {
        String newName(String prefix);

        String newActionId();

        List<Map<String, Object>> ask(String className, Map<String, Value> bindings);

        /** The unfinished actions, of one robot unless {@code robot} is null (oldest first). */
        List<Action.Unfinished> unfinished(String robot);
    }

    private final KnowledgeBase kb;
    private final Services services;

    ScriptApi(KnowledgeBase kb, Services services) {
        this.kb = kb;
        this.services = services;
    }

    /** Globals for a script of {@code frame}; {@code s} is built by {@code self}; effects go to {@code effects}. */
    Map<String, Object> globals(Supplier<Object> self, List<Effect> effects, String frame) {
        Map<String, Object> g = new LinkedHashMap<>();
        g.put("s", self.get());
        HostFunction sendmsg = args -> {
            need(args, 2, "sendmsg(target, text)");
            String id = services.newActionId();
            effects.add(new Effect.Issue(id, FrameView.nameOf(args.get(0)), "say", List.of(String.valueOf(args.get(1)))));
            return id;
        };
        g.put("sendmsg", sendmsg);
        g.put("Sendmsg", sendmsg);
        g.put("command", (HostFunction) args -> {
            need(args, 2, "command(robot, action, args)");
            List<String> rest = new ArrayList<>();
            for (Object o : args.subList(2, args.size())) {
                if (o instanceof List<?> l) {
                    l.forEach(x -> rest.add(String.valueOf(x)));
                } else {
                    rest.add(String.valueOf(o));
                }
            }
            String id = services.newActionId();
            effects.add(new Effect.Issue(id, FrameView.nameOf(args.get(0)), String.valueOf(args.get(1)), rest));
            return id;
        });
        g.put("create", (HostFunction) args -> {
            need(args, 1, "create(class, slots)");
            String cls = FrameView.nameOf(args.get(0));
            String name = services.newName(cls);
            effects.add(new Effect.Create(name, cls, slotValues(cls, args.size() > 1 ? args.get(1) : Map.of())));
            return name;
        });
        g.put("destroy", (HostFunction) args -> {
            need(args, 1, "destroy(instance)");
            effects.add(new Effect.Destroy(FrameView.nameOf(args.get(0))));
            return true;
        });
        g.put("cancel", (HostFunction) args -> {
            need(args, 1, "cancel(actionIdOrRobot, reason)");
            effects.add(new Effect.Cancel(FrameView.nameOf(args.get(0)), args.size() > 1
                    ? String.valueOf(args.get(1)) : "cancelled by frame '" + frame + "'"));
            return true;
        });
        g.put("actions", (HostFunction) args -> {
            List<Map<String, Object>> out = new ArrayList<>();
            for (Action.Unfinished u : services.unfinished(args.isEmpty() ? null : FrameView.nameOf(args.get(0)))) {
                Map<String, Object> a = new LinkedHashMap<>();
                a.put("id", u.action().id());
                a.put("robot", u.action().robot());
                a.put("target", u.action().target());
                a.put("name", u.action().name());
                a.put("args", u.action().args());
                a.put("frame", u.action().frame());
                a.put("instance", u.action().instance());
                a.put("status", u.status().name().toLowerCase(Locale.ROOT));
                out.add(a);
            }
            return out;
        });
        g.put("ask", (HostFunction) args -> {
            need(args, 1, "ask(class, bindings)");
            String cls = FrameView.nameOf(args.get(0));
            return services.ask(cls, slotValues(cls, args.size() > 1 ? args.get(1) : Map.of()));
        });
        g.put("log", (HostFunction) args -> {
            LOG.info("[{}] {}", frame, String.join(" ", args.stream().map(String::valueOf).toList()));
            return true;
        });
        g.put("frameName", (HostFunction) args -> {
            need(args, 1, "frameName(text)");
            return Frame.nameFor(String.valueOf(args.get(0)));
        });
        g.put("frameExists", (HostFunction) args -> {
            need(args, 1, "frameExists(name)");
            return kb.contains(FrameView.nameOf(args.get(0)));
        });
        g.put("learn", (HostFunction) args -> {
            need(args, 2, "learn(name, parentClass, slots)");
            String name = String.valueOf(args.get(0));
            String parent = FrameView.nameOf(args.get(1));
            Frame.Builder b = Frame.classFrame(name).parent(parent).provenance(Provenance.LEARNED);
            if (args.size() > 2 && args.get(2) instanceof Map<?, ?> m) {
                m.forEach((k, v) -> b.slot(Slot.ofValue(String.valueOf(k), DataType.STRING, Value.of(String.valueOf(v)))));
            }
            effects.add(new Effect.Learn(b.build()));
            return name;
        });
        return g;
    }

    private Map<String, Value> slotValues(String cls, Object slots) {
        Map<String, Value> out = new LinkedHashMap<>();
        if (!(slots instanceof Map<?, ?> m)) {
            return out;
        }
        for (Map.Entry<?, ?> e : m.entrySet()) {
            String slot = String.valueOf(e.getKey());
            DataType type = kb.contains(cls) ? kb.slot(cls, slot).map(x -> x.slot().type()).orElse(null) : null;
            out.put(slot, toValue(e.getValue(), type));
        }
        return out;
    }

    static Value toValue(Object o, DataType type) {
        if (type == DataType.INSTANCE || type == DataType.FRAME || o instanceof FrameView
                || (o instanceof Map<?, ?> m && m.containsKey(FrameView.NAME))) {
            return Value.ref(FrameView.nameOf(o));
        }
        return switch (o) {
            case Boolean b -> Value.of(b);
            case Integer i -> Value.of((long) i);
            case Long l -> Value.of(l);
            case Number n -> n.doubleValue() == Math.rint(n.doubleValue()) && type == DataType.INTEGER
                    ? Value.of(n.longValue()) : Value.of(n.doubleValue());
            case List<?> l -> new Value.Lst(l.stream().map(x -> toValue(x, null)).toList());
            case null -> throw new InferenceException("A script passed no value where a slot value was expected.");
            default -> type == null || type == DataType.STRING ? Value.of(o.toString()) : Value.parse(type, o.toString());
        };
    }

    private static void need(List<Object> args, int n, String signature) {
        if (args.size() < n) {
            throw new InferenceException("Script function " + signature + " needs " + n + " arguments but got "
                    + args.size() + ".");
        }
    }
}
