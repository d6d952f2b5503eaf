package org.kicnp.protocol;

/** The closed set of error codes of an {@link Message.ErrorReply}; {@code docs/protocol.md} says which close the connection. */
public enum ErrorCode {
    FRAME_TOO_LARGE(true),
    BAD_JSON(true),
    UNSUPPORTED_VERSION(true),
    UNKNOWN_TYPE(true),
    BAD_MESSAGE(true),
    NOT_AUTHENTICATED(true),
    FORBIDDEN(false),
    UNKNOWN_AGENT(false),
    UNKNOWN_FRAME(false),
    REJECTED(false),
    AGENT_DISCONNECTED(false),
    HEARTBEAT_TIMEOUT(true),
    OVERLOADED(true),
    SUPERSEDED(true),
    INTERNAL(true);

    private final boolean closesConnection;

    ErrorCode(boolean closesConnection) {
        this.closesConnection = closesConnection;
    }

    /** Whether the server closes the connection after sending this error. */
    public boolean closesConnection() {
        return closesConnection;
    }
}
