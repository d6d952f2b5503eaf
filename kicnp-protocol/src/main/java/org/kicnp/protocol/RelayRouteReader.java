package org.kicnp.protocol;

import java.util.Objects;
import java.util.Optional;

/**
 * Reads the {@link RelayRoute} of one connection's relays, as {@link MessageCodec#relayRoute} does, but keeping its
 * scanner from payload to payload and giving the same route instance again while the routing members repeat: a hub
 * reading an agent that keeps writing to the same peer then allocates nothing per relay for its route (the scanner,
 * the route and its {@code Optional}s were over half of what the gateway allocated per relay). Not thread-safe: one
 * per connection, used on its event loop.
 */
public final class RelayRouteReader {
    private final RelayScanner scanner = new RelayScanner();

    /**
     * The route of a payload that is a plain relay; empty for any other payload (see {@link RelayRoute}).
     *
     * @throws IndexOutOfBoundsException when the range is not within {@code payload}
     */
    public Optional<RelayRoute> read(byte[] payload, int offset, int length) {
        Objects.checkFromIndexSize(offset, length, payload.length);
        return Optional.ofNullable(scanner.scan(payload, offset, length));
    }
}
