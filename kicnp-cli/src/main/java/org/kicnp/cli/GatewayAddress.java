package org.kicnp.cli;

/**
 * Where a verb finds a running server's gateway: {@code HOST:PORT}, the port after the last colon, so that an IPv6
 * address in brackets ({@code [::1]:7777}) works too.
 */
record GatewayAddress(String host, int port) {

    /**
     * Reads {@code HOST:PORT}.
     *
     * @throws IllegalArgumentException saying what {@code --gateway} should look like
     */
    static GatewayAddress parse(String text) {
        return parse(text, "--gateway", 1);
    }

    /**
     * Reads {@code HOST:PORT} given to {@code option}, whose port may be {@code lowestPort} (0: any free port) to
     * 65535.
     *
     * @throws IllegalArgumentException saying what {@code option} should look like
     */
    static GatewayAddress parse(String text, String option, int lowestPort) {
        int colon = text.lastIndexOf(':');
        String host = colon < 0 ? "" : text.substring(0, colon);
        if (host.startsWith("[") && host.endsWith("]")) {
            host = host.substring(1, host.length() - 1);
        }
        int port;
        try {
            port = Integer.parseInt(text.substring(colon + 1));
        } catch (NumberFormatException e) {
            port = -1;
        }
        if (host.isEmpty() || port < lowestPort || port > 65535) {
            throw new IllegalArgumentException(option + " '" + text + "' is not HOST:PORT with a port from "
                    + lowestPort + " to 65535.");
        }
        return new GatewayAddress(host, port);
    }
}
