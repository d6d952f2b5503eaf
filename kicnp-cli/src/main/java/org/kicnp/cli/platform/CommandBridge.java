package org.kicnp.cli.platform;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Value;
import org.kicnp.gateway.ActionSink;
import org.kicnp.gateway.FeedbackListener;
import org.kicnp.inference.Action;
import org.kicnp.inference.ActionFeedback;
import org.kicnp.protocol.Message.Command;
import org.kicnp.robots.ActionSpec;
import org.kicnp.robots.ArgSpec;
import org.kicnp.robots.RobotModels;

/**
 * The two adapters between the inference engine and the gateway. Outward, an engine {@link Action} becomes a
 * gateway {@link Command}: the robot frame's {@code agent} slot (else its name in lower case) names the agent, and
 * the script's positional arguments become named ones — {@code "name=value"} as written, otherwise in the order
 * of the robot's action specification ({@code command(s.mScout, "go_to", 6.85, 3.7)} gives {@code x}, {@code y}).
 * Inward, the gateway's feedback drives the engine's action life cycle. Both directions are logged.
 */
final class CommandBridge implements org.kicnp.inference.ActionSink, FeedbackListener {
    private final KnowledgeBase kb;
    private final EventLog log;
    private volatile ActionSink gateway = c -> { };
    private volatile ActionFeedback engine;

    CommandBridge(KnowledgeBase kb, EventLog log) {
        this.kb = kb;
        this.log = log;
    }

    void connect(ActionSink gatewaySink, ActionFeedback engineFeedback) {
        this.gateway = gatewaySink;
        this.engine = engineFeedback;
    }

    @Override public void send(Action action) {
        String agent = agentOf(action.robot());
        Map<String, String> args = namedArgs(agent, action.name(), action.args());
        Command c = new Command(action.id(), agent, action.name(), args);
        Map<String, Object> f = new LinkedHashMap<>();
        f.put("id", action.id());
        f.put("robot", agent);
        f.put("action", action.name());
        f.put("args", args);
        f.put("frame", action.frame());
        f.put("instance", action.instance());
        f.put("startAt", action.startAt());
        log.record("command", f);
        try {
            gateway.send(c);
        } catch (RuntimeException e) {
            if (engine != null) {
                engine.actionFailed(action.id(), e.getMessage());
            }
        }
    }

    /** The engine gave up on an action (it timed out) or cancelled it: the robot is asked to stop. */
    @Override public void cancel(Action action, String reason) {
        String agent = agentOf(action.robot());
        log.record("cancel", Map.of("id", action.id(), "robot", agent, "reason", reason));
        gateway.cancel(agent, action.id(), reason);
    }

    private String agentOf(String robotFrame) {
        return kb.frame(robotFrame).flatMap(f -> kb.value(robotFrame, "agent")).map(Value::text)
                .orElse(robotFrame.toLowerCase(Locale.ROOT));
    }

    static Map<String, String> namedArgs(String agent, String actionName, List<String> given) {
        Optional<List<ArgSpec>> specs = RobotModels.all().stream().filter(m -> m.name().equals(agent)).findFirst()
                .flatMap(m -> m.action(actionName)).map(ActionSpec::args);
        Map<String, String> out = new LinkedHashMap<>();
        int position = 0;
        for (String arg : given) {
            int eq = arg.indexOf('=');
            if (eq > 0 && arg.substring(0, eq).matches("[A-Za-z_][A-Za-z0-9_]*")) {
                out.put(arg.substring(0, eq), arg.substring(eq + 1));
            } else if (specs.isPresent() && position < specs.get().size()) {
                out.put(specs.get().get(position++).name(), arg);
            } else {
                out.put("arg" + position++, arg);
            }
        }
        return out;
    }

    @Override public void started(Command command) {
        feedback(command, "started", "");
        if (engine != null && isEngines(command)) {
            engine.actionStarted(command.id());
        }
    }

    @Override public void ended(Command command, String result) {
        feedback(command, "ended", result);
        if (engine != null && isEngines(command)) {
            engine.actionEnded(command.id(), result);
        }
    }

    @Override public void failed(Command command, String reason) {
        feedback(command, "failed", reason);
        if (engine != null && isEngines(command)) {
            engine.actionFailed(command.id(), reason);
        }
    }

    /** Whether the engine issued the command (tele-operated ones it does not track). */
    private static boolean isEngines(Command c) {
        return !c.id().startsWith(PlatformTeleOperation.ID_PREFIX);
    }

    private void feedback(Command c, String stage, String detail) {
        log.record("feedback", Map.of("id", c.id(), "robot", c.robot(), "action", c.action(), "stage", stage,
                "detail", detail));
    }

}
