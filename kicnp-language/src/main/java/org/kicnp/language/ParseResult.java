package org.kicnp.language;

import static java.util.Objects.requireNonNull;

/** What the parser made of a sentence: a case frame, or a polite request to say it again. Never a guess. */
public sealed interface ParseResult {
    /** The reply Robovie gives when it did not understand. */
    String SAY_AGAIN = "Sorry, I didn't catch that. Could you say it again?";

    /** The sentence was understood. */
    record Parsed(CaseFrame frame) implements ParseResult {
        public Parsed {
            requireNonNull(frame, "frame");
        }
    }

    /** The sentence was not understood: why (for logs and tests) and what to say to the speaker. */
    record NotUnderstood(String reason, String reply) implements ParseResult {
        public NotUnderstood {
            requireNonNull(reason, "reason");
            requireNonNull(reply, "reply");
        }

        /** Not understood, with the standard polite reply. */
        public static NotUnderstood because(String reason) {
            return new NotUnderstood(reason, SAY_AGAIN);
        }
    }
}
