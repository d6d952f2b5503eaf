package org.kicnp.editor;

import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;
import org.kicnp.editor.RobotCapabilities.ActionSpec;
import org.kicnp.editor.RobotCapabilities.ArgSpec;
import org.kicnp.editor.WorldSnapshot.Cup;
import org.kicnp.editor.WorldSnapshot.Robot;
import org.kicnp.editor.WorldSnapshot.Room;
import org.kicnp.editor.WorldSnapshot.RunningAction;
import org.kicnp.editor.WorldSnapshot.User;

/**
 * A small in-test platform behind the editor's three ports, recording what the editor asks of it: the world is
 * whatever {@link #publish} last gave it; the chat answers every line with a verdict and Robovie's reply; a
 * command to a known robot starts at once and ends (or fails, for {@code fail_me}) right after, but Scout's
 * {@code patrol}, which runs until it is stopped (as does the world's running action {@code c9}).
 */
final class TestPlatform implements WorldView, ChatPort, TeleOperation {
    final List<String> said = new CopyOnWriteArrayList<>();
    final List<String> sent = new CopyOnWriteArrayList<>();
    final List<String> judged = new CopyOnWriteArrayList<>();
    final List<String> stopped = new CopyOnWriteArrayList<>();
    /** The commands running until stopped, by id: robot and action. */
    private final Map<String, String[]> running = new java.util.concurrent.ConcurrentHashMap<>(
            Map.of("c9", new String[] {"scout", "go_to"}));
    private final AtomicReference<WorldSnapshot> latest = new AtomicReference<>();
    private final List<Consumer<WorldSnapshot>> worldListeners = new CopyOnWriteArrayList<>();
    private final List<Consumer<ChatLine>> chatListeners = new CopyOnWriteArrayList<>();
    private final List<Consumer<CommandFeedback>> feedbackListeners = new CopyOnWriteArrayList<>();
    private final AtomicInteger ids = new AtomicInteger();

    PlatformPorts ports() {
        return PlatformPorts.none().withWorld(this).withChat(this).withTeleOperation(this);
    }

    /** The simulator's opening scene: Robovie, Scout going to the counter, alice at the door, four cups. */
    static WorldSnapshot scene(double t) {
        return new WorldSnapshot(t, Room.SIMULATOR,
                List.of(new Robot("robovie", "humanoid", 4.0, 3.2, -90, List.of(), "arms down/down"),
                        new Robot("scout", "mobile", 6.2, 2.0 + t / 10, 90,
                                List.of(new RunningAction("base", "c9", "go_to")), "moving 0.30 m/s"),
                        new Robot("aibo", "quadruped", 2.5, 2.0, 0, List.of(), "posture sit")),
                List.of(new User("alice", 4.0, 0.6, 90)),
                List.of(new Cup("tea-1", "tea", 7.3, 3.7, ""), new Cup("coffee-1", "coffee", 7.3, 4.6, "")),
                List.of(new WorldSnapshot.Obstacle("box", 3.0, 4.5, 1.0, 0.2)));
    }

    void publish(WorldSnapshot s) {
        latest.set(s);
        worldListeners.forEach(l -> l.accept(s));
    }

    @Override public Optional<WorldSnapshot> latest() {
        return Optional.ofNullable(latest.get());
    }

    @Override public Subscription onSnapshot(Consumer<WorldSnapshot> listener) {
        worldListeners.add(listener);
        return () -> worldListeners.remove(listener);
    }

    @Override public void say(String speaker, String text) {
        said.add(speaker + ": " + text);
        if (text.toLowerCase(java.util.Locale.ROOT).contains("tea")) {
            chat(new ChatLine(Instant.now(), speaker, ChatLine.Kind.UNDERSTOOD, "request: bring tea to " + speaker));
            chat(new ChatLine(Instant.now(), "Robovie", ChatLine.Kind.ROBOT, "Scout will bring you tea."));
        } else {
            chat(new ChatLine(Instant.now(), speaker, ChatLine.Kind.NOT_UNDERSTOOD,
                    "No verb I know. Please say it again."));
        }
    }

    private void chat(ChatLine line) {
        chatListeners.forEach(l -> l.accept(line));
    }

    @Override public Subscription onLine(Consumer<ChatLine> listener) {
        chatListeners.add(listener);
        return () -> chatListeners.remove(listener);
    }

    @Override public List<RobotCapabilities> robots() {
        return List.of(
                new RobotCapabilities("robovie", "humanoid", List.of(
                        new ActionSpec("say", "Say a sentence.", List.of(new ArgSpec("text", "string", true))),
                        new ActionSpec("fail_me", "Always fails.", List.of()))),
                new RobotCapabilities("scout", "mobile", List.of(
                        new ActionSpec("go_to", "Go to (x, y).", List.of(new ArgSpec("x", "number", true),
                                new ArgSpec("y", "number", true))),
                        new ActionSpec("patrol", "Patrol the room until stopped.", List.of()))));
    }

    @Override public String send(String robot, String action, Map<String, String> args) {
        RobotCapabilities r = robots().stream().filter(c -> c.name().equals(robot)).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("There is no robot '" + robot + "'."));
        if (r.actions().stream().noneMatch(a -> a.name().equals(action))) {
            throw new IllegalArgumentException("Robot '" + robot + "' has no action '" + action + "'.");
        }
        String id = "tele-" + ids.incrementAndGet();
        sent.add(id + " " + robot + " " + action + " " + new java.util.TreeMap<>(args));
        if (action.equals("patrol")) {
            running.put(id, new String[] {robot, action});
        }
        Thread.ofVirtual().start(() -> {
            feedback(new CommandFeedback(Instant.now(), id, robot, action, CommandFeedback.Status.STARTED, ""));
            if (action.equals("patrol")) {
                return;
            }
            feedback(action.equals("fail_me")
                    ? new CommandFeedback(Instant.now(), id, robot, action, CommandFeedback.Status.FAILED, "told to fail")
                    : new CommandFeedback(Instant.now(), id, robot, action, CommandFeedback.Status.ENDED, "done"));
        });
        return id;
    }

    private void feedback(CommandFeedback f) {
        try {
            Thread.sleep(50);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        feedbackListeners.forEach(l -> l.accept(f));
    }

    @Override public void markWrong(String actionId, String reason) {
        if (!actionId.startsWith("tele-") && !actionId.equals("c9")) {
            throw new IllegalArgumentException("No action '" + actionId + "' is known.");
        }
        judged.add(actionId + ": " + reason);
    }

    @Override public void stop(String actionId, String reason) {
        String[] r = running.remove(actionId);
        if (r == null) {
            throw new IllegalArgumentException("No action '" + actionId + "' is running.");
        }
        stopped.add(actionId + ": " + reason);
        Thread.ofVirtual().start(() -> feedback(new CommandFeedback(Instant.now(), actionId, r[0], r[1],
                CommandFeedback.Status.FAILED, "cancelled: " + reason)));
    }

    @Override public Subscription onFeedback(Consumer<CommandFeedback> listener) {
        feedbackListeners.add(listener);
        return () -> feedbackListeners.remove(listener);
    }
}
