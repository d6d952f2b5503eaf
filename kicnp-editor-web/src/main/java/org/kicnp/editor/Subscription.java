package org.kicnp.editor;

/**
 * A listener registration on one of the platform ports ({@link WorldView}, {@link ChatPort}, {@link TeleOperation}):
 * closing it stops the deliveries. Closing twice does nothing.
 */
@FunctionalInterface
public interface Subscription extends AutoCloseable {
    /** Stops delivering events to the listener. */
    @Override void close();
}
