package org.kicnp.cli.platform;

import static java.nio.charset.StandardCharsets.UTF_8;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The run's event log: every {@link PlatformEvent} as one JSON line ({@code {"t":…,"event":"fired",…}}), flushed
 * per line so a crashed run still leaves its story, and handed to the subscribers (the console printer of
 * {@code demo} and {@code replay}, the replay's checks, the chat and tele-operation). Thread-safe.
 *
 * <p>{@link #record} stamps the event (its times are the caller's) and queues it; one writer thread turns it into
 * JSON, writes and flushes the line, then hands it to the subscribers, in the order recorded. The inference
 * engine's trace records from the engine's thread, often hundreds of events for one stimulus (a script condition
 * false for each feedback so far): written there, JSON and the write took a third of that thread's time in a Table
 * 5 replay, between a person speaking and the robot's answer. The queue is bounded ({@link #CAPACITY}): a recorder
 * that outruns the disk waits, as it did when it wrote itself, rather than filling the heap. {@link #awaitWritten}
 * waits until what was recorded before it is written and handed on; {@link #close} writes everything queued first.
 */
public final class EventLog implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(EventLog.class);
    private static final ObjectMapper JSON = new ObjectMapper();
    static final int CAPACITY = 16_384;
    /** Queued after the last event by {@link #close}: the writer stops there. */
    private static final Object STOP = new Object();

    private final Path file;
    private final Writer out;
    private final BlockingQueue<Object> queue = new ArrayBlockingQueue<>(CAPACITY);
    private final List<Consumer<PlatformEvent>> subscribers = new CopyOnWriteArrayList<>();
    private final Thread writer;
    private volatile boolean closed;
    /** Whether a failed write was logged (once: a full disk fails every line after). Writer thread only. */
    private boolean failureLogged;

    private EventLog(Path file, Writer out) {
        this.file = file;
        this.out = out;
        this.writer = Thread.ofPlatform().daemon().name("event-log").unstarted(this::writeQueued);
        writer.start();
    }

    /** Opens (appending) the log file, creating its directory. */
    public static EventLog open(Path file) {
        try {
            Path dir = file.toAbsolutePath().getParent();
            Files.createDirectories(dir);
            return new EventLog(file, Files.newBufferedWriter(file, UTF_8, StandardOpenOption.CREATE,
                    StandardOpenOption.APPEND));
        } catch (IOException e) {
            throw new UncheckedIOException("Cannot open the event log '" + file + "': " + e.getMessage(), e);
        }
    }

    public Path file() {
        return file;
    }

    /** Hands every event recorded from now on to {@code subscriber}, on the log's writer thread, in order. */
    public void subscribe(Consumer<PlatformEvent> subscriber) {
        subscribers.add(subscriber);
    }

    public void unsubscribe(Consumer<PlatformEvent> subscriber) {
        subscribers.remove(subscriber);
    }

    /** Records an event now: stamped here, written and handed to the subscribers by the writer thread. */
    public void record(String kind, Map<String, Object> fields) {
        PlatformEvent e = PlatformEvent.now(kind, fields);
        if (closed) {
            LOG.debug("Event '{}' recorded after the event log '{}' was closed; not written.", kind, file);
            return;
        }
        try {
            queue.put(e);
        } catch (InterruptedException ex) {
            Thread.currentThread().interrupt();
            LOG.warn("Interrupted while recording event '{}' in the event log '{}'; it is not written.", kind, file);
        }
    }

    /**
     * Waits until every event recorded before this call has been written (and flushed) and handed to the
     * subscribers, or {@code timeout} has passed; returns whether it has.
     */
    public boolean awaitWritten(Duration timeout) throws InterruptedException {
        if (closed) {
            writer.join(timeout);
            return !writer.isAlive();
        }
        CountDownLatch done = new CountDownLatch(1);
        if (!queue.offer(done, timeout.toMillis(), TimeUnit.MILLISECONDS)) {
            return false;
        }
        return done.await(timeout.toMillis(), TimeUnit.MILLISECONDS);
    }

    /** The writer thread: each queued event written, flushed and handed on, until {@link #STOP}. */
    private void writeQueued() {
        while (true) {
            Object next;
            try {
                next = queue.take();
            } catch (InterruptedException e) {
                return; // not interrupted by the log itself; close() stops it with STOP
            }
            if (next == STOP) {
                return;
            }
            if (next instanceof CountDownLatch done) {
                done.countDown();
                continue;
            }
            PlatformEvent e = (PlatformEvent) next;
            write(e);
            for (Consumer<PlatformEvent> s : subscribers) {
                try {
                    s.accept(e);
                } catch (RuntimeException ex) {
                    LOG.warn("A subscriber of the event log failed on event '{}': {}", e.kind(), ex.toString(), ex);
                }
            }
        }
    }

    private void write(PlatformEvent e) {
        ObjectNode line = JSON.createObjectNode();
        line.put("t", e.epochMillis());
        line.put("event", e.kind());
        e.fields().forEach((k, v) -> line.set(k, JSON.valueToTree(v)));
        try {
            out.write(line.toString());
            out.write('\n');
            out.flush();
        } catch (IOException | RuntimeException ex) {
            if (!failureLogged) {
                failureLogged = true;
                LOG.error("Cannot write the event log '{}' (event '{}'; later failures are not logged): {}", file,
                        e.kind(), ex.getMessage(), ex);
            }
        }
    }

    /** Writes what is queued, stops the writer thread and closes the file. */
    @Override public void close() {
        if (closed) {
            return;
        }
        closed = true;
        try {
            queue.put(STOP);
            writer.join(TimeUnit.SECONDS.toMillis(10));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        if (writer.isAlive()) {
            LOG.warn("The event log '{}' did not finish writing in 10 s; closing it anyway.", file);
        }
        try {
            out.close();
        } catch (IOException e) {
            throw new UncheckedIOException("Cannot close the event log '" + file + "': " + e.getMessage(), e);
        }
    }
}
