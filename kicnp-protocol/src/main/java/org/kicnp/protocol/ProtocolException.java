package org.kicnp.protocol;

import static java.util.Objects.requireNonNull;

/** A message that breaks the wire protocol: unreadable, unknown, or not allowed. Carries the code to answer with. */
public class ProtocolException extends RuntimeException {
    private final ErrorCode code;

    public ProtocolException(ErrorCode code, String message) {
        super(message);
        this.code = requireNonNull(code, "code");
    }

    public ProtocolException(ErrorCode code, String message, Throwable cause) {
        super(message, cause);
        this.code = requireNonNull(code, "code");
    }

    /** The error code the peer is told. */
    public ErrorCode code() {
        return code;
    }
}
