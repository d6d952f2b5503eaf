package org.kicnp.cli.platform;

import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.BiPredicate;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.kicnp.core.BatchRejectedException;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.kicnp.editor.CommandFeedback;
import org.kicnp.editor.RobotCapabilities;
import org.kicnp.editor.Subscription;
import org.kicnp.editor.TeleOperation;
import org.kicnp.gateway.ActionSink;
import org.kicnp.protocol.Message.Command;
import org.kicnp.robots.ActionSpec;
import org.kicnp.robots.RobotModel;
import org.kicnp.robots.RobotModels;

/**
 * Tele-operation from the editor (paper section 3.2) and the person's judgement of actions (section 3.3). The robots
 * offered are the connected agents that have a robot model; a command goes straight to the gateway's
 * {@link ActionSink} with an id of its own ({@code tele-N}, which the inference engine does not track), and is
 * logged like the engine's commands. Feedback on every command — tele-operated or issued by the engine — is read
 * from the event log. {@code markWrong} asserts a RUNTIME {@code WrongAction} instance, adding the class when the
 * knowledge base lacks it, so behavior frames can match the judgement. {@code stop} cancels a tele-operated command
 * at the gateway (the robot's agent halts it) and an action the engine issued through the engine (which fails it,
 * and what waits on it, and asks the robot to stop it).
 */
final class PlatformTeleOperation implements TeleOperation, AutoCloseable {
    /** The prefix of tele-operated command ids. */
    static final String ID_PREFIX = "tele-";
    /** The class of the judgement instances. */
    static final String WRONG_ACTION = "WrongAction";
    private static final int REMEMBERED = 1024;

    private final KnowledgeBase kb;
    private final EventLog log;
    private final Supplier<List<String>> connected;
    private final Supplier<ActionSink> gateway;
    private final BiPredicate<String, String> engineCancel;
    private final AtomicLong counter = new AtomicLong();
    private final Listeners<CommandFeedback> listeners = new Listeners<>();
    private final Consumer<PlatformEvent> watcher = this::watch;
    /** Recent commands by id: robot and action. Guarded by itself. */
    private final Map<String, String[]> commands = new LinkedHashMap<>(16, 0.75f, false) {
        @Override protected boolean removeEldestEntry(Map.Entry<String, String[]> eldest) {
            return size() > REMEMBERED;
        }
    };

    /**
     * @param engineCancel cancels an unfinished action of the engine, given its id and the reason; false when the
     *                     engine has no such action ({@code InferenceEngine.cancelAction})
     */
    PlatformTeleOperation(KnowledgeBase kb, EventLog log, Supplier<List<String>> connected, Supplier<ActionSink> gateway,
                          BiPredicate<String, String> engineCancel) {
        this.kb = kb;
        this.log = log;
        this.connected = connected;
        this.gateway = gateway;
        this.engineCancel = engineCancel;
        log.subscribe(watcher);
    }

    @Override public List<RobotCapabilities> robots() {
        List<String> agents = connected.get();
        List<RobotCapabilities> out = new ArrayList<>();
        for (RobotModel m : RobotModels.all()) {
            if (agents.contains(m.name())) {
                out.add(new RobotCapabilities(m.name(), "", m.actions().stream().map(PlatformTeleOperation::spec).toList()));
            }
        }
        return out;
    }

    private static RobotCapabilities.ActionSpec spec(ActionSpec a) {
        return new RobotCapabilities.ActionSpec(a.simAction(), a.doc(), a.args().stream()
                .map(g -> new RobotCapabilities.ArgSpec(g.name(), typeName(g.type()), g.required())).toList());
    }

    private static String typeName(DataType t) {
        return switch (t) {
            case INTEGER, FLOAT -> "number";
            case STRING -> "string";
            case BOOLEAN -> "boolean";
            default -> t.name().toLowerCase(Locale.ROOT);
        };
    }

    @Override public String send(String robot, String action, Map<String, String> args) {
        RobotModel model = RobotModels.all().stream().filter(m -> m.name().equals(robot)).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("There is no robot named '" + robot + "'."));
        ActionSpec spec = model.action(action).orElseThrow(() -> new IllegalArgumentException(
                "The robot '" + robot + "' has no action '" + action + "'."));
        spec.args().stream().filter(a -> a.required() && !args.containsKey(a.name())).findFirst().ifPresent(a -> {
            throw new IllegalArgumentException("The action '" + action + "' of '" + robot + "' needs the argument '"
                    + a.name() + "'.");
        });
        if (!connected.get().contains(robot)) {
            throw new IllegalStateException("The robot '" + robot + "' is not connected.");
        }
        String id = ID_PREFIX + counter.incrementAndGet();
        Map<String, Object> f = new LinkedHashMap<>();
        f.put("id", id);
        f.put("robot", robot);
        f.put("action", spec.simAction());
        f.put("args", Map.copyOf(args));
        f.put("frame", "tele-operation");
        log.record("command", f);
        gateway.get().send(new Command(id, robot, spec.simAction(), Map.copyOf(args)));
        return id;
    }

    @Override public void markWrong(String actionId, String reason) {
        String[] known;
        synchronized (commands) {
            known = commands.get(actionId);
        }
        if (known == null) {
            throw new IllegalArgumentException("No action with the id '" + actionId + "' is known.");
        }
        ensureClass();
        Frame wrong = Frame.instance(WRONG_ACTION + "-" + actionId.replaceAll("[^A-Za-z0-9_-]", "_"), WRONG_ACTION)
                .provenance(Provenance.RUNTIME)
                .slot(Slot.ofValue("action", DataType.STRING, Value.of(actionId)))
                .slot(Slot.ofValue("robot", DataType.STRING, Value.of(known[0])))
                .slot(Slot.ofValue("name", DataType.STRING, Value.of(known[1])))
                .slot(Slot.ofValue("reason", DataType.STRING, Value.of(reason == null ? "" : reason)))
                .slot(Slot.ofValue("judgedBy", DataType.STRING, Value.of("editor")))
                .build();
        kb.put(wrong);
        log.record("wrong", Map.of("id", actionId, "robot", known[0], "action", known[1], "reason", reason == null ? "" : reason));
    }

    @Override public void stop(String actionId, String reason) {
        String why = reason + " (asked in the editor)";
        boolean stopping;
        if (actionId.startsWith(ID_PREFIX)) {
            String[] known;
            synchronized (commands) {
                known = commands.get(actionId);
            }
            stopping = known != null && gateway.get().cancel(known[0], actionId, why);
        } else {
            stopping = engineCancel.test(actionId, why);
        }
        if (!stopping) {
            throw new IllegalArgumentException("No action with the id '" + actionId + "' is running.");
        }
        log.record("stop", Map.of("id", actionId, "reason", reason));
    }

    private void ensureClass() {
        if (kb.contains(WRONG_ACTION)) {
            return;
        }
        Frame.Builder b = Frame.classFrame(WRONG_ACTION).provenance(Provenance.RUNTIME);
        if (kb.frame("System").map(f -> !f.isInstance()).orElse(false)) {
            b.parent("System");
        }
        for (String slot : List.of("action", "robot", "name", "reason", "judgedBy")) {
            b.slot(Slot.builder(slot, DataType.STRING).build());
        }
        try {
            kb.add(b.build());
        } catch (BatchRejectedException e) {
            if (!kb.contains(WRONG_ACTION)) {
                throw e;
            }
        }
    }

    @Override public Subscription onFeedback(Consumer<CommandFeedback> listener) {
        return listeners.add(listener);
    }

    private void watch(PlatformEvent e) {
        switch (e.kind()) {
            case "command" -> {
                synchronized (commands) {
                    commands.put(e.text("id"), new String[] {e.text("robot"), e.text("action")});
                }
            }
            case "feedback" -> status(e.text("stage")).ifPresent(s -> listeners.emit(new CommandFeedback(
                    Instant.ofEpochMilli(e.epochMillis()), e.text("id"), e.text("robot"), e.text("action"), s,
                    e.text("detail"))));
            default -> { }
        }
    }

    private static Optional<CommandFeedback.Status> status(String stage) {
        return switch (stage) {
            case "started" -> Optional.of(CommandFeedback.Status.STARTED);
            case "ended" -> Optional.of(CommandFeedback.Status.ENDED);
            case "failed" -> Optional.of(CommandFeedback.Status.FAILED);
            default -> Optional.empty();
        };
    }

    @Override public void close() {
        log.unsubscribe(watcher);
    }
}
