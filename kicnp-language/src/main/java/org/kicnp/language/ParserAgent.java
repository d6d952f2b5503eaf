package org.kicnp.language;

import static java.util.Objects.requireNonNull;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicLong;
import org.kicnp.agent.AgentBase;
import org.kicnp.agent.AgentException;
import org.kicnp.agent.AgentOptions;
import org.kicnp.core.Frame;
import org.kicnp.protocol.Message;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The paper's "software agent to parse a sentence", a service agent. A user agent (or Robovie's agent, for what
 * its microphone heard) relays a sentence to it with subject {@code utterance} — or {@code utterance:name},
 * {@code utterance:drink} when Robovie has just asked for a name or a drink. The agent parses it and asserts the
 * case frame as a RUNTIME instance ({@code said-<speaker>-<n>}, speaker = the relaying agent) for behaviour frames
 * to match, then relays back to the speaker {@code understood} (body: the instance's name) or, when it did not
 * understand, asserts a {@code SaidUnknown} instance and relays {@code say-again} with the polite reply. It
 * registers the class frames of {@link LanguageFrames} as its capabilities, so a knowledge base has them whenever
 * the parser is connected. It keeps the latest {@value #KEEP} instances it asserted and destroys older ones, so a long
 * conversation does not fill the knowledge base.
 */
public final class ParserAgent extends AgentBase {
    /** The subject of a relay carrying a sentence. */
    public static final String SUBJECT = "utterance";
    /** The subject of the reply when the sentence was understood. */
    public static final String UNDERSTOOD = "understood";
    /** The subject of the reply asking the speaker to say it again. */
    public static final String SAY_AGAIN = "say-again";

    /** How many of its instances the agent leaves in the knowledge base. */
    public static final int KEEP = 64;

    private static final Logger LOG = LoggerFactory.getLogger(ParserAgent.class);

    /** The subject to relay a sentence with: {@code utterance}, or {@code utterance:name} after a question for a name. */
    public static String subject(Expectation expectation) {
        return switch (requireNonNull(expectation, "expectation")) {
            case NONE -> SUBJECT;
            case NAME, DRINK -> SUBJECT + ":" + expectation.name().toLowerCase(Locale.ROOT);
        };
    }

    private final SentenceParser parser;
    private final AtomicLong counter = new AtomicLong();
    /** Touched only on the SDK's single event thread. */
    private final Deque<String> asserted = new ArrayDeque<>();

    public ParserAgent(AgentOptions options, SentenceParser parser) {
        super(options);
        this.parser = requireNonNull(parser, "parser");
    }

    @Override protected List<Frame> capabilities() {
        return LanguageFrames.classes();
    }

    @Override protected void onRelay(Message.Relay relay) {
        String subject = relay.subject();
        if (!subject.equals(SUBJECT) && !subject.startsWith(SUBJECT + ":")) {
            LOG.debug("Ignoring a relay from '{}' with subject '{}'.", relay.from(), subject);
            return;
        }
        Expectation expectation = expectation(subject);
        String speaker = relay.from();
        String instance = "said-" + safe(speaker) + "-" + counter.incrementAndGet();
        String text = shortened(relay.body());
        try {
            switch (parser.parse(relay.body(), expectation)) {
                case ParseResult.Parsed p -> {
                    assertFrame(CaseFrames.toFrame(p.frame(), instance, speaker));
                    remember(instance);
                    LOG.debug("'{}' said '{}': {}", speaker, text, p.frame());
                    relayTo(speaker, UNDERSTOOD, instance);
                }
                case ParseResult.NotUnderstood n -> {
                    assertFrame(CaseFrames.unknown(n, text, instance, speaker));
                    remember(instance);
                    LOG.debug("Did not understand '{}' from '{}': {}", text, speaker, n.reason());
                    relayTo(speaker, SAY_AGAIN, n.reply());
                }
            }
        } catch (AgentException e) {
            LOG.warn("Could not handle '{}' from '{}': {}", text, speaker, e.getMessage());
        }
    }

    /** Keeps the instance's name, destroying the oldest beyond {@link #KEEP}. */
    private void remember(String instance) {
        asserted.addLast(instance);
        while (asserted.size() > KEEP) {
            String old = asserted.removeFirst();
            try {
                destroy(old);
            } catch (AgentException e) { // a behaviour frame may have consumed it already
                LOG.debug("Could not destroy '{}': {}", old, e.getMessage());
            }
        }
    }

    private static Expectation expectation(String subject) {
        int colon = subject.indexOf(':');
        if (colon < 0) {
            return Expectation.NONE;
        }
        String name = subject.substring(colon + 1).toUpperCase(Locale.ROOT);
        for (Expectation e : Expectation.values()) {
            if (e.name().equals(name)) {
                return e;
            }
        }
        LOG.warn("Unknown expectation '{}' in subject '{}'; parsing without one.", name, subject);
        return Expectation.NONE;
    }

    /**
     * The sentence as the instance keeps it: a paste longer than the parser reads is cut there, so the instance
     * asserted stays far below the gateway's frame limit (which closes the connection of an agent that sends more).
     */
    private static String shortened(String body) {
        return body.length() <= SentenceParser.MAX_LENGTH ? body : body.substring(0, SentenceParser.MAX_LENGTH) + "…";
    }

    /** Keeps the characters a frame name may hold. */
    private static String safe(String speaker) {
        StringBuilder sb = new StringBuilder();
        for (char c : speaker.toCharArray()) {
            sb.append(Character.isLetterOrDigit(c) || c == '_' || c == '-' ? c : '_');
        }
        return sb.toString();
    }
}
