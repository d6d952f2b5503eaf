package org.kicnp.bench;

import static java.util.Objects.requireNonNull;

import java.util.Optional;

/** Both hubs at one agent count; Mosquitto's figures are empty when it was skipped or failed (see the note). */
record RelayRun(int agents, int window, HubFigures kicnp, Optional<HubFigures> mosquitto, Optional<String> note) {
    RelayRun {
        requireNonNull(kicnp, "kicnp");
        requireNonNull(mosquitto, "mosquitto");
        requireNonNull(note, "note");
    }

    /** K-ICNP's throughput over Mosquitto's, when both were measured. */
    Optional<Double> ratio() {
        return mosquitto.filter(m -> m.msgsPerSecond() > 0).map(m -> kicnp.msgsPerSecond() / m.msgsPerSecond());
    }
}
