package org.kicnp.cli.platform;

import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.function.Supplier;
import org.kicnp.agent.AgentBase;
import org.kicnp.agent.AgentException;
import org.kicnp.agent.AgentOptions;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.editor.ChatLine;
import org.kicnp.editor.ChatPort;
import org.kicnp.editor.Subscription;
import org.kicnp.language.Expectation;
import org.kicnp.language.ParserAgent;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Message;

/**
 * The editor's chat box on the platform: a person's words go to the sentence parser exactly as the scenario's
 * User A speaks them — through a user agent (a "microphone") named after the speaker ({@code "User A"} →
 * {@code userA}), connected to the gateway with that agent's token, relaying with subject {@code utterance} — so
 * the parser asserts the case frame with that agent as the speaker. The parser's reply ({@code understood} or
 * {@code say-again}) comes back as a verdict line; what the robots are commanded to {@code say} comes back as
 * robot lines (from the event log). Like User A's microphone in the terminal demo, the chat hears the robots: after a
 * robot line that asks for a name or a drink ("What is your name?") the words are relayed with that expectation
 * ({@code utterance:name}, {@link Expectation#after}), so a name or a drink said alone ("Ken.", "Lemonade.") is
 * understood as one. A speaker without a token in the agent file is refused.
 */
final class PlatformChat implements ChatPort, AutoCloseable {
    private static final Duration CONNECT = Duration.ofSeconds(10);

    private final int gatewayPort;
    private final Function<String, Optional<String>> tokens;
    /** The agents registered with the gateway now, so a speaker already connected elsewhere is not taken over. */
    private final Supplier<List<String>> registered;
    private final KnowledgeBase kb;
    private final EventLog log;
    private final Listeners<ChatLine> listeners = new Listeners<>();
    private final Map<String, Microphone> microphones = new ConcurrentHashMap<>();
    private final Consumer<PlatformEvent> robotSpeech = this::robotSpeech;
    /** What the robots' last line asked for, the same for every speaker in the room. */
    private volatile Expectation asked = Expectation.NONE;

    PlatformChat(int gatewayPort, Function<String, Optional<String>> tokens, Supplier<List<String>> registered,
                 KnowledgeBase kb, EventLog log) {
        this.gatewayPort = gatewayPort;
        this.tokens = tokens;
        this.registered = registered;
        this.kb = kb;
        this.log = log;
        log.subscribe(robotSpeech);
    }

    /** The agent name a speaker's words are relayed under: {@code "User A"} → {@code userA}. */
    static String agentName(String speaker) {
        String joined = speaker.strip().replaceAll("[^A-Za-z0-9_-]", "");
        return joined.isEmpty() ? joined : joined.substring(0, 1).toLowerCase(Locale.ROOT) + joined.substring(1);
    }

    @Override public void say(String speaker, String text) {
        if (text == null || text.isBlank()) {
            throw new IllegalArgumentException("There is nothing to say: the text is empty.");
        }
        String agent = agentName(speaker == null ? "" : speaker);
        String token = tokens.apply(agent).orElseThrow(() -> new IllegalArgumentException("The speaker '" + speaker
                + "' is not known to the platform: the agent file has no token for '" + agent + "'."));
        if (!microphones.containsKey(agent) && registered.get().contains(agent)) {
            // Connecting under that name would replace the agent already there (the demo's User A at its terminal).
            throw new IllegalArgumentException("'" + speaker + "' is connected already as agent '" + agent
                    + "' (in the demo, at its terminal): speak there, or here as another person.");
        }
        Microphone mic = microphones.computeIfAbsent(agent, a -> connect(a, speaker, token));
        log.record("user_said", Map.of("user", agent, "text", text));
        try {
            mic.relayTo("parser", ParserAgent.subject(asked), text);
        } catch (AgentException e) {
            throw new IllegalStateException("Cannot pass the words of '" + speaker + "' to the parser: "
                    + e.getMessage(), e);
        }
    }

    private Microphone connect(String agent, String speaker, String token) {
        Microphone mic = new Microphone(AgentOptions.of("127.0.0.1", gatewayPort, agent, AgentKind.USER, token),
                speaker);
        try {
            mic.startAndAwait(CONNECT);
            return mic;
        } catch (RuntimeException e) {
            mic.close();
            throw new IllegalStateException("Cannot connect the microphone of '" + speaker + "' to the gateway: "
                    + e.getMessage(), e);
        }
    }

    @Override public Subscription onLine(Consumer<ChatLine> listener) {
        return listeners.add(listener);
    }

    private void robotSpeech(PlatformEvent e) {
        if (e.kind().equals("command") && e.text("action").equals("say")
                && e.fields().get("args") instanceof Map<?, ?> args && args.get("text") != null) {
            asked = Expectation.after(args.get("text").toString());
            listeners.emit(new ChatLine(Instant.ofEpochMilli(e.epochMillis()), display(e.text("robot")),
                    ChatLine.Kind.ROBOT, args.get("text").toString()));
        }
    }

    private static String display(String agent) {
        return agent.isEmpty() ? agent : agent.substring(0, 1).toUpperCase(Locale.ROOT) + agent.substring(1);
    }

    /** What the parser made of it: the class of the asserted instance and its name. */
    private String understood(String instance) {
        return kb.frame(instance).flatMap(f -> f.parent()).map(c -> c + " (" + instance + ")").orElse(instance);
    }

    @Override public void close() {
        log.unsubscribe(robotSpeech);
        microphones.values().forEach(Microphone::close);
        microphones.clear();
    }

    /** One speaker's user agent: it hears the parser's verdicts. */
    private final class Microphone extends AgentBase {
        private final String speaker;

        Microphone(AgentOptions options, String speaker) {
            super(options);
            this.speaker = speaker;
        }

        @Override protected void onRelay(Message.Relay relay) {
            Instant now = Instant.now();
            switch (relay.subject()) {
                case ParserAgent.UNDERSTOOD -> listeners.emit(new ChatLine(now, speaker, ChatLine.Kind.UNDERSTOOD,
                        understood(relay.body())));
                case ParserAgent.SAY_AGAIN -> listeners.emit(new ChatLine(now, speaker, ChatLine.Kind.NOT_UNDERSTOOD,
                        relay.body()));
                default -> { }
            }
        }
    }
}
