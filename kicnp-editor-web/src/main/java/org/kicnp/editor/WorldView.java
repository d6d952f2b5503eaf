package org.kicnp.editor;

import java.util.Optional;
import java.util.function.Consumer;

/**
 * Port: the simulated (or real) room as the platform last saw it. The editor draws it on the page's World panel,
 * answers {@code GET /api/world} with {@link #latest()} and pushes every snapshot to the page as a {@code world}
 * event (at most 10 per second; when snapshots come faster, only the newest of each 100 ms is sent).
 *
 * <p>{@code ./kicnp serve} implements it over the simulator's {@code state} events
 * ({@link SimulatorState#snapshot} maps one to a {@link WorldSnapshot}).
 */
public interface WorldView {
    /** The newest snapshot, or empty before the world has reported anything. */
    Optional<WorldSnapshot> latest();

    /**
     * Calls {@code listener} with every new snapshot, from any thread, until the subscription is closed. The
     * listener must return quickly; the editor only queues the snapshot for sending.
     */
    Subscription onSnapshot(Consumer<WorldSnapshot> listener);
}
