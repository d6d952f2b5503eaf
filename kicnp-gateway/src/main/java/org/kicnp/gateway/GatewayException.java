package org.kicnp.gateway;

/** A failure of the gateway itself: it cannot bind, or its configuration is wrong. */
public class GatewayException extends RuntimeException {
    public GatewayException(String message) {
        super(message);
    }

    public GatewayException(String message, Throwable cause) {
        super(message, cause);
    }
}
