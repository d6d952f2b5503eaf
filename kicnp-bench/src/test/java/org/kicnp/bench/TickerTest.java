package org.kicnp.bench;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** {@link Ticker}: the open loop's 1 ms clock. */
class TickerTest {
    private static final long MS = TimeUnit.MILLISECONDS.toNanos(1);

    @Test
    void start_ticksOnTheGridUpToAndIncludingTheEnd_neverBeforeAGridTime_thenEnds() throws Exception {
        List<Long> ticks = new CopyOnWriteArrayList<>();
        long start = RelayLoop.now() + 5 * MS;
        long until = start + 50 * MS;

        Ticker ticker = Ticker.start(() -> ticks.add(RelayLoop.now()), start, until);
        ticker.awaitEnd();

        assertThat(ticks).isNotEmpty().allSatisfy(t -> assertThat(t).isGreaterThanOrEqualTo(start));
        assertThat(ticks.get(ticks.size() - 1)).isGreaterThanOrEqualTo(until);
        // Each tick falls at or after a grid time it has not ticked for yet: never two for one grid time, never early.
        for (int k = 1; k < ticks.size(); k++) {
            long gridBefore = (ticks.get(k - 1) - start) / MS;
            long grid = (ticks.get(k) - start) / MS;
            assertThat(grid).as("tick %d", k).isGreaterThan(gridBefore);
        }
        // A late wake-up ticks once for all that is due, so there are at most 51 ticks (start, +1 ms, ..., until).
        assertThat(ticks.size()).isBetween(10, 51);
    }

    @Test
    void stop_beforeTheEnd_stopsTicking() throws Exception {
        List<Long> ticks = new CopyOnWriteArrayList<>();
        long start = RelayLoop.now();
        Ticker ticker = Ticker.start(() -> ticks.add(RelayLoop.now()), start, start + TimeUnit.MINUTES.toNanos(1));
        Thread.sleep(20);

        ticker.stop();
        int after = ticks.size();
        Thread.sleep(20);

        assertThat(after).isPositive();
        assertThat(ticks).hasSize(after);
    }
}
