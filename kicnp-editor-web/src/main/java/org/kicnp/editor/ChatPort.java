package org.kicnp.editor;

import java.util.function.Consumer;

/**
 * Port: a person speaking to the robots through the editor's chat box, as if they stood in the room
 * ({@code POST /api/chat}). The platform relays the words to the sentence parser (the {@code ParserAgent}, subject
 * {@code utterance}, or {@code utterance:name} / {@code utterance:drink} right after a robot asked for a name or a
 * drink, so that "Ken." alone answers "What is your name?") and reports what followed as {@link ChatLine}s: the
 * parser's verdict (understood, or "say it again" with its reason) and what the robots said. The editor shows the
 * person's own line itself.
 */
public interface ChatPort {
    /**
     * Passes {@code text}, spoken by {@code speaker} (for example {@code "User A"}), to the platform. Returns at
     * once; the replies arrive through {@link #onLine}.
     *
     * @throws IllegalArgumentException when the platform refuses the line (unknown speaker, empty text); the
     *     message is shown to the person (422)
     * @throws IllegalStateException when the platform cannot take it now (503)
     */
    void say(String speaker, String text);

    /** Calls {@code listener} with every reply line, from any thread, until the subscription is closed. */
    Subscription onLine(Consumer<ChatLine> listener);
}
