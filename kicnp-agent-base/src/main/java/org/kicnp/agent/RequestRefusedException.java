package org.kicnp.agent;

import static java.util.Objects.requireNonNull;

import org.kicnp.protocol.ErrorCode;

/** The server answered a request with an error, such as an unknown frame or a batch the knowledge base refused. */
public final class RequestRefusedException extends AgentException {
    private final ErrorCode code;

    public RequestRefusedException(ErrorCode code, String message) {
        super(message);
        this.code = requireNonNull(code, "code");
    }

    /** The protocol's error code. */
    public ErrorCode code() {
        return code;
    }
}
