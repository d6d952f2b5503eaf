package org.kicnp.cli;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.time.Instant;
import java.time.format.DateTimeParseException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.kicnp.core.Value;
import org.kicnp.protocol.ChangeKind;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.ValueJson;

/**
 * The file {@code kicnp agent record} writes and {@code kicnp agent play} reads: JSON lines, a header first, then
 * one line per change heard, in the order heard. A sensor signal's line holds what a {@code sensor} message needs to
 * send it again (agent, sensor, values typed as the protocol carries them, ttlMs); a frame of another recorded class
 * is kept as its XML, for reading beside the signals, and is not played.
 */
final class Bag {
    static final String FORMAT = "kicnp-bag";
    static final int VERSION = 1;
    private static final ObjectMapper JSON = new ObjectMapper()
            .enable(com.fasterxml.jackson.databind.DeserializationFeature.FAIL_ON_TRAILING_TOKENS);

    private Bag() {
    }

    /** One line of a bag. */
    sealed interface Line permits Header, Signal, Removal, FrameChange {
    }

    /** The first line: when and where the recording was made, and of which classes. */
    record Header(Instant started, String gateway, List<String> classes) implements Line {
    }

    /** A signal added or replaced at {@code t} ms after the start: what a {@code sensor} message sends again. */
    record Signal(long t, ChangeKind change, String agent, String sensor, List<Value> values, Optional<Long> ttlMs)
            implements Line {
    }

    /** A signal gone at {@code t} (its agent left, its time to live ran out, or it was destroyed). */
    record Removal(long t, String agent, String sensor) implements Line {
    }

    /** A change of a frame that is no sensor signal: kept for reading, not played. */
    record FrameChange(long t, ChangeKind change, String instance, Optional<String> ofClass, Optional<String> frame)
            implements Line {
    }

    /** A line as JSON text, without a line break. */
    static String write(Line line) {
        ObjectNode o = JSON.createObjectNode();
        switch (line) {
            case Header h -> {
                o.put("format", FORMAT);
                o.put("version", VERSION);
                o.put("started", h.started().toString());
                o.put("gateway", h.gateway());
                ArrayNode classes = o.putArray("classes");
                h.classes().forEach(classes::add);
            }
            case Signal s -> {
                o.put("t", s.t());
                o.put("event", event(s.change()));
                o.put("agent", s.agent());
                o.put("sensor", s.sensor());
                ArrayNode values = o.putArray("values");
                s.values().forEach(v -> values.add(ValueJson.toJson(v)));
                s.ttlMs().ifPresent(ttl -> o.put("ttlMs", ttl));
            }
            case Removal r -> {
                o.put("t", r.t());
                o.put("event", "removed");
                o.put("agent", r.agent());
                o.put("sensor", r.sensor());
            }
            case FrameChange f -> {
                o.put("t", f.t());
                o.put("event", event(f.change()));
                o.put("instance", f.instance());
                f.ofClass().ifPresent(c -> o.put("class", c));
                f.frame().ifPresent(x -> o.put("frame", x));
            }
        }
        return o.toString();
    }

    private static String event(ChangeKind c) {
        return c.name().toLowerCase(Locale.ROOT);
    }

    /** A bag read in full: its header, and its other lines each with its line number. */
    record Recording(Header header, List<Numbered> lines) {
    }

    /** A line and where it is in the file (1-based). */
    record Numbered(int number, Line line) {
    }

    /**
     * Reads a whole bag; blank lines are skipped.
     *
     * @throws IllegalArgumentException {@code FILE:LINE: what is wrong}, for the first line that is not as the format
     *     says (or the file cannot be read)
     */
    static Recording read(Path file) {
        List<String> text;
        try {
            text = Files.readAllLines(file, StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            throw new IllegalArgumentException("There is no bag file '" + file + "'.");
        } catch (IOException | UncheckedIOException e) {
            throw new IllegalArgumentException("Cannot read the bag file '" + file + "': " + e.getMessage());
        }
        Header header = null;
        List<Numbered> lines = new ArrayList<>();
        long last = 0;
        for (int i = 0; i < text.size(); i++) {
            if (text.get(i).isBlank()) {
                continue;
            }
            String where = file + ":" + (i + 1) + ": ";
            try {
                JsonNode node = JSON.readTree(text.get(i));
                if (node == null || !node.isObject()) {
                    throw new IllegalArgumentException("the line is not a JSON object.");
                }
                if (header == null) {
                    header = header(node);
                    continue;
                }
                Line line = line(node);
                long t = time(line);
                if (t < last) {
                    throw new IllegalArgumentException("'t' " + t + " is before the " + last
                            + " of the line above: times must not go back.");
                }
                last = t;
                lines.add(new Numbered(i + 1, line));
            } catch (JsonProcessingException e) {
                throw new IllegalArgumentException(where + "the line is not JSON: " + e.getOriginalMessage());
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException(where + e.getMessage(), e);
            }
        }
        if (header == null) {
            throw new IllegalArgumentException(file + ":1: the bag is empty; it starts with a header line {\"format\": \""
                    + FORMAT + "\", \"version\": " + VERSION + ", ...}.");
        }
        return new Recording(header, lines);
    }

    /** The time of a line, ms after the start. */
    static long time(Line line) {
        return switch (line) {
            case Header h -> 0;
            case Signal s -> s.t();
            case Removal r -> r.t();
            case FrameChange f -> f.t();
        };
    }

    private static Header header(JsonNode o) {
        if (!FORMAT.equals(o.path("format").asText(null))) {
            throw new IllegalArgumentException("the first line is not a header of a " + FORMAT + " ({\"format\": \""
                    + FORMAT + "\", \"version\": " + VERSION + ", ...}).");
        }
        if (!o.path("version").isIntegralNumber() || o.get("version").asLong() != VERSION) {
            throw new IllegalArgumentException("the bag's version is " + o.path("version") + "; this kicnp reads "
                    + "version " + VERSION + ".");
        }
        Instant started;
        try {
            started = Instant.parse(text(o, "started"));
        } catch (DateTimeParseException e) {
            throw new IllegalArgumentException("'started' is not a time such as 2026-01-31T12:00:00Z.");
        }
        List<String> classes = new ArrayList<>();
        for (JsonNode c : o.path("classes")) {
            classes.add(c.asText());
        }
        return new Header(started, o.path("gateway").asText(""), List.copyOf(classes));
    }

    private static Line line(JsonNode o) {
        JsonNode t = o.get("t");
        if (t == null || !t.isIntegralNumber() || !t.canConvertToLong() || t.asLong() < 0) {
            throw new IllegalArgumentException("'t' (ms since the start) must be a whole number of 0 or more, not "
                    + (t == null ? "missing" : t.toString()) + ".");
        }
        ChangeKind change = change(text(o, "event"));
        if (o.has("sensor")) {
            String agent = name(o, "agent");
            String sensor = name(o, "sensor");
            if (change == ChangeKind.REMOVED) {
                return new Removal(t.asLong(), agent, sensor);
            }
            JsonNode values = o.get("values");
            if (values == null || !values.isArray()) {
                throw new IllegalArgumentException("'values' must be an array of the signal's values.");
            }
            List<Value> read = new ArrayList<>();
            for (JsonNode v : values) {
                read.add(ValueJson.fromJson(v, bad -> new IllegalArgumentException("'values' holds " + bad
                        + ", which is no slot value: items are numbers, true or false, \"text\", {\"ref\": \"NAME\"} "
                        + "or lists.")));
            }
            return new Signal(t.asLong(), change, agent, sensor, List.copyOf(read), ttl(o.get("ttlMs")));
        }
        if (o.has("instance")) {
            return new FrameChange(t.asLong(), change, text(o, "instance"), optionalText(o, "class"),
                    optionalText(o, "frame"));
        }
        throw new IllegalArgumentException("the line has neither 'sensor' (a signal) nor 'instance' (a frame).");
    }

    private static Optional<Long> ttl(JsonNode ttl) {
        if (ttl == null || ttl.isNull()) {
            return Optional.empty();
        }
        if (!ttl.isIntegralNumber() || !ttl.canConvertToLong() || ttl.asLong() < 1
                || ttl.asLong() > Message.SensorSignal.MAX_TTL_MS) {
            throw new IllegalArgumentException("'ttlMs' must be a whole number from 1 to "
                    + Message.SensorSignal.MAX_TTL_MS + ", not " + ttl + ".");
        }
        return Optional.of(ttl.asLong());
    }

    private static ChangeKind change(String event) {
        return switch (event) {
            case "added" -> ChangeKind.ADDED;
            case "replaced" -> ChangeKind.REPLACED;
            case "removed" -> ChangeKind.REMOVED;
            default -> throw new IllegalArgumentException("'event' must be added, replaced or removed, not '" + event
                    + "'.");
        };
    }

    private static String name(JsonNode o, String member) {
        String name = text(o, member);
        if (!Message.NAME.matcher(name).matches()) {
            throw new IllegalArgumentException("'" + member + "' '" + name + "' is not a name: use letters, digits, "
                    + "'_' and '-', starting with a letter or '_'.");
        }
        return name;
    }

    private static String text(JsonNode o, String member) {
        JsonNode n = o.get(member);
        if (n == null || !n.isTextual()) {
            throw new IllegalArgumentException("'" + member + "' must be text, not " + (n == null ? "missing"
                    : n.toString()) + ".");
        }
        return n.textValue();
    }

    private static Optional<String> optionalText(JsonNode o, String member) {
        return o.hasNonNull(member) ? Optional.of(text(o, member)) : Optional.empty();
    }
}
