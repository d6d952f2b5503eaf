package org.kicnp.editor;

import com.fasterxml.jackson.databind.JsonNode;
import java.time.Instant;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.function.Supplier;

/**
 * The World panel's API over the {@link PlatformPorts}: the world snapshot, the chat, tele-operation and "this
 * action was wrong". Subscribes to the ports once the server runs ({@link #attach}) and pushes {@code world},
 * {@code chat} and {@code feedback} events to the pages. A missing port answers 503 with a sentence.
 */
final class PlatformResource implements AutoCloseable {
    static final String DEFAULT_SPEAKER = "User A";
    static final int CHAT_HISTORY = 200;
    static final int MAX_CHAT_TEXT = 500;

    private final PlatformPorts ports;
    private final CommandLog commands = new CommandLog();
    private final Deque<Map<String, Object>> chat = new ArrayDeque<>();
    private final List<Subscription> subscriptions = new ArrayList<>();
    private WorldThrottle throttle;
    private EventHub events;

    PlatformResource(PlatformPorts ports) {
        this.ports = ports;
    }

    /** Starts forwarding the ports' events to the pages. */
    synchronized void attach(EventHub hub) {
        this.events = hub;
        ports.world().ifPresent(w -> {
            throttle = new WorldThrottle(s -> hub.publish("world", Map.of("snapshot", s)));
            subscriptions.add(w.onSnapshot(throttle));
        });
        ports.chat().ifPresent(c -> subscriptions.add(c.onLine(this::line)));
        ports.teleOperation().ifPresent(t -> subscriptions.add(t.onFeedback(
                f -> hub.publish("feedback", commands.feedback(f)))));
    }

    /** Which ports are connected, for {@code GET /api/session}. */
    Map<String, Object> status() {
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("world", ports.world().isPresent());
        out.put("chat", ports.chat().isPresent());
        out.put("teleOperation", ports.teleOperation().isPresent());
        return out;
    }

    /** {@code GET /api/world}: the latest snapshot, or empty (204) before the first. */
    Optional<WorldSnapshot> world() {
        return port(ports.world().orElse(null), "world view").latest();
    }

    /** {@code GET /api/chat}: the recent lines, oldest first. */
    synchronized List<Map<String, Object>> chatLines() {
        port(ports.chat().orElse(null), "chat");
        return List.copyOf(chat);
    }

    /** {@code POST /api/chat}: {@code {text, speaker?}}; answers the person's line, which is also pushed. */
    Map<String, Object> say(JsonNode body) {
        ChatPort port = port(ports.chat().orElse(null), "chat");
        String text = FrameInput.text(body, "text").map(String::strip).orElse("");
        String speaker = FrameInput.text(body, "speaker").map(String::strip).filter(s -> !s.isEmpty())
                .orElse(DEFAULT_SPEAKER);
        if (text.isEmpty()) {
            throw new ApiException(400, "Say something: the chat line is empty.");
        }
        if (text.length() > MAX_CHAT_TEXT || speaker.length() > 100) {
            throw new ApiException(400, "A chat line is at most " + MAX_CHAT_TEXT + " characters long.");
        }
        Map<String, Object> line = line(new ChatLine(Instant.now(), speaker, ChatLine.Kind.USER, text));
        call(() -> {
            port.say(speaker, text);
            return null;
        });
        return line;
    }

    /** {@code GET /api/robots}: the robots and their actions. */
    List<RobotCapabilities> robots() {
        return call(() -> teleOperation().robots());
    }

    /** {@code POST /api/robots/{robot}/commands}: {@code {action, args}}; answers the command's row. */
    Map<String, Object> send(String robot, JsonNode body) {
        TeleOperation port = teleOperation();
        String action = FrameInput.text(body, "action").map(String::strip).orElse("");
        if (action.isEmpty()) {
            throw new ApiException(400, "Name the action to send to '" + robot + "' (\"action\").");
        }
        Map<String, String> args = new LinkedHashMap<>();
        JsonNode given = body.path("args");
        if (!given.isMissingNode() && !given.isNull() && !given.isObject()) {
            throw new ApiException(400, "\"args\" must be an object of argument names to values.");
        }
        given.fields().forEachRemaining(e -> args.put(e.getKey(), e.getValue().isValueNode()
                ? e.getValue().asText() : e.getValue().toString()));
        String id = call(() -> port.send(robot, action, Map.copyOf(args)));
        return published(commands.sent(id, robot, action, args));
    }

    /** {@code GET /api/commands}: recent commands, newest first. */
    List<Map<String, Object>> commands() {
        teleOperation();
        return commands.recent();
    }

    /** {@code POST /api/actions/{id}/wrong}: {@code {reason}}. */
    Map<String, Object> wrong(String id, JsonNode body) {
        TeleOperation port = teleOperation();
        String reason = FrameInput.text(body, "reason").map(String::strip).orElse("");
        if (reason.isEmpty()) {
            throw new ApiException(400, "Say why action '" + id + "' was wrong (\"reason\").");
        }
        call(() -> {
            port.markWrong(id, reason);
            return null;
        });
        return published(commands.wrong(id, reason));
    }

    /** {@code POST /api/actions/{id}/stop}: {@code {reason}} (optional): the action is cancelled, the robot halts. */
    Map<String, Object> stop(String id, JsonNode body) {
        TeleOperation port = teleOperation();
        String reason = FrameInput.text(body, "reason").map(String::strip).filter(x -> !x.isEmpty())
                .orElse("stopped in the editor");
        call(() -> {
            port.stop(id, reason);
            return null;
        });
        return published(commands.stopAsked(id, reason));
    }

    /** Pushes a command's row as it now is to the page's live events ({@code feedback}); answers the row. */
    private Map<String, Object> published(Map<String, Object> row) {
        EventHub hub = hub();
        if (hub != null) {
            hub.publish("feedback", row);
        }
        return row;
    }

    private TeleOperation teleOperation() {
        return port(ports.teleOperation().orElse(null), "tele-operation");
    }

    private synchronized EventHub hub() {
        return events;
    }

    private Map<String, Object> line(ChatLine l) {
        Map<String, Object> row = new LinkedHashMap<>();
        row.put("at", l.at().toString());
        row.put("speaker", l.speaker());
        row.put("kind", l.kind().name().toLowerCase(Locale.ROOT));
        row.put("text", l.text());
        EventHub hub;
        synchronized (this) {
            chat.addLast(row);
            while (chat.size() > CHAT_HISTORY) {
                chat.removeFirst();
            }
            hub = events;
        }
        if (hub != null) {
            hub.publish("chat", row);
        }
        return row;
    }

    private static <T> T port(T port, String what) {
        if (port == null) {
            throw new ApiException(503, "This editor is not connected to a platform, so there is no " + what
                    + " (start the platform with ./kicnp serve).");
        }
        return port;
    }

    /** Runs a port call, turning its refusals into answers: bad input 422, not possible now 503. */
    private static <T> T call(Supplier<T> body) {
        try {
            return body.get();
        } catch (IllegalArgumentException e) {
            throw new ApiException(422, e.getMessage());
        } catch (IllegalStateException e) {
            throw new ApiException(503, e.getMessage());
        }
    }

    @Override public synchronized void close() {
        subscriptions.forEach(Subscription::close);
        subscriptions.clear();
        if (throttle != null) {
            throttle.close();
        }
        events = null;
    }
}
