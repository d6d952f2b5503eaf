package org.kicnp.cli.platform;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The event log writes and hands on events on its own thread, in the order recorded, and loses none on close. */
class EventLogTest {
    @TempDir
    Path dir;

    @Test
    void record_doesNotWaitForTheWriteOrTheSubscribers_andTheyGetEveryEventInOrder() throws Exception {
        Path file = dir.resolve("logs/events.jsonl");
        CountDownLatch release = new CountDownLatch(1);
        List<String> seen = new CopyOnWriteArrayList<>();
        List<String> threads = new CopyOnWriteArrayList<>();
        try (EventLog log = EventLog.open(file)) {
            log.subscribe(e -> {
                threads.add(Thread.currentThread().getName());
                try {
                    release.await(3, TimeUnit.SECONDS); // a slow subscriber (a console, a check)
                } catch (InterruptedException ex) {
                    Thread.currentThread().interrupt();
                }
                seen.add(e.text("n"));
            });
            for (int i = 0; i < 3; i++) {
                log.record("fired", Map.of("n", i));
            }
            // Had record handed the events on itself, each would have waited out the held subscriber here.
            assertThat(seen).as("recorded without waiting for the held subscriber").isEmpty();

            release.countDown();
            for (int i = 3; i < 100; i++) {
                log.record("fired", Map.of("n", i));
            }
            assertThat(log.awaitWritten(Duration.ofSeconds(10))).isTrue();
            assertThat(seen).hasSize(100).containsExactlyElementsOf(
                    java.util.stream.IntStream.range(0, 100).mapToObj(String::valueOf).toList());
            assertThat(threads).containsOnly("event-log");
            List<String> lines = Files.readAllLines(file);
            assertThat(lines).hasSize(100);
            assertThat(lines.getFirst()).startsWith("{\"t\":").contains("\"event\":\"fired\"", "\"n\":0");
            assertThat(lines.getLast()).contains("\"n\":99");
        }
    }

    @Test
    void close_writesWhatIsStillQueued_andARecordAfterCloseIsDroppedQuietly() throws Exception {
        Path file = dir.resolve("events.jsonl");
        EventLog log = EventLog.open(file);
        CountDownLatch release = new CountDownLatch(1);
        log.subscribe(e -> {
            try {
                release.await(2, TimeUnit.SECONDS);
            } catch (InterruptedException ex) {
                Thread.currentThread().interrupt();
            }
        });
        for (int i = 0; i < 50; i++) {
            log.record("fact", Map.of("n", i));
        }
        release.countDown();
        log.close();

        assertThat(Files.readAllLines(file)).hasSize(50);
        log.record("late", Map.of()); // the platform's threads may still report while it stops
        assertThat(Files.readAllLines(file)).hasSize(50);
    }

    @Test
    void aFailingSubscriber_doesNotStopTheOthersNorTheLog() throws Exception {
        Path file = dir.resolve("events.jsonl");
        List<String> seen = new CopyOnWriteArrayList<>();
        try (EventLog log = EventLog.open(file)) {
            log.subscribe(e -> {
                throw new IllegalStateException("broken subscriber");
            });
            log.subscribe(e -> seen.add(e.kind()));
            log.record("a", Map.of());
            log.record("b", Map.of());
            assertThat(log.awaitWritten(Duration.ofSeconds(10))).isTrue();
        }
        assertThat(seen).containsExactly("a", "b");
        assertThat(Files.readAllLines(file)).hasSize(2);
    }
}
