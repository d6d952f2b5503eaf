package org.kicnp.cli.platform;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;
import org.kicnp.editor.Subscription;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The listeners of one editor port: adding gives a {@link Subscription} that removes the listener again; a listener
 * that throws is logged and does not stop the others.
 */
final class Listeners<T> {
    private static final Logger LOG = LoggerFactory.getLogger(Listeners.class);

    private final List<Consumer<T>> listeners = new CopyOnWriteArrayList<>();

    Subscription add(Consumer<T> listener) {
        listeners.add(java.util.Objects.requireNonNull(listener, "listener"));
        return () -> listeners.remove(listener);
    }

    void emit(T item) {
        for (Consumer<T> l : listeners) {
            try {
                l.accept(item);
            } catch (RuntimeException e) {
                LOG.warn("A port listener failed on {}: {}", item, e.getMessage(), e);
            }
        }
    }
}
