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
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Consumer;

/**
 * The run's event log: every {@link PlatformEvent} as one JSON line ({@code {"t":…,"event":"fired",…}}), flushed
 * per line so a crashed run still leaves its story, and handed to the subscribers (the console printer of
 * {@code demo} and {@code replay}, the replay's checks). Thread-safe.
 */
public final class EventLog implements AutoCloseable {
    private static final ObjectMapper JSON = new ObjectMapper();

    private final Path file;
    private final Writer out;
    private final ReentrantLock lock = new ReentrantLock();
    private final List<Consumer<PlatformEvent>> subscribers = new CopyOnWriteArrayList<>();

    private EventLog(Path file, Writer out) {
        this.file = file;
        this.out = out;
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

    public void subscribe(Consumer<PlatformEvent> subscriber) {
        subscribers.add(subscriber);
    }

    public void unsubscribe(Consumer<PlatformEvent> subscriber) {
        subscribers.remove(subscriber);
    }

    /** Records an event now. */
    public void record(String kind, Map<String, Object> fields) {
        PlatformEvent e = PlatformEvent.now(kind, fields);
        ObjectNode line = JSON.createObjectNode();
        line.put("t", e.epochMillis());
        line.put("event", kind);
        fields.forEach((k, v) -> line.set(k, JSON.valueToTree(v)));
        lock.lock();
        try {
            out.write(line.toString());
            out.write('\n');
            out.flush();
        } catch (IOException ex) {
            throw new UncheckedIOException("Cannot write the event log '" + file + "': " + ex.getMessage(), ex);
        } finally {
            lock.unlock();
        }
        for (Consumer<PlatformEvent> s : subscribers) {
            s.accept(e);
        }
    }

    @Override public void close() {
        lock.lock();
        try {
            out.close();
        } catch (IOException e) {
            throw new UncheckedIOException("Cannot close the event log '" + file + "': " + e.getMessage(), e);
        } finally {
            lock.unlock();
        }
    }
}
