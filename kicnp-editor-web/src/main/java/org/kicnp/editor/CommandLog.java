package org.kicnp.editor;

import java.time.Instant;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The recent commands the World panel lists ({@code GET /api/commands}): each with its arguments, its latest
 * status ({@code sent}, {@code started}, {@code ended}, {@code failed}), the result or reason, the person's "wrong"
 * judgement and the reason they gave when they asked for it to be stopped ({@code stop}). Keeps the newest {@link #LIMIT}; feedback for commands sent elsewhere (by the platform's
 * behavior frames) is listed too, so any action can be judged.
 */
final class CommandLog {
    static final int LIMIT = 50;

    private final LinkedHashMap<String, Map<String, Object>> entries = new LinkedHashMap<>();
    /**
     * Counts every change to any row; a row's {@code rev} is the count at its last change. Rows reach a page by two
     * roads that can overtake each other (the answer to a send, stop or "wrong", and the {@code feedback} events that
     * feedback from another thread pushes), so a page keeps, of two copies of a row, the one with the higher
     * {@code rev}: a stop's answer taken before the cancellation's feedback never turns a failed command back into a
     * started one.
     */
    private long revision;

    /** Records a command the editor sent; answers its row. */
    synchronized Map<String, Object> sent(String id, String robot, String action, Map<String, String> args) {
        Map<String, Object> row = row(id, robot, action);
        row.put("args", Collections.unmodifiableMap(new LinkedHashMap<>(args)));
        return changed(row);
    }

    /** Records feedback; answers the command's row as it now is. */
    synchronized Map<String, Object> feedback(CommandFeedback f) {
        Map<String, Object> row = row(f.commandId(), f.robot(), f.action());
        row.put("status", f.status().name().toLowerCase(Locale.ROOT));
        row.put("detail", f.detail());
        row.put("at", f.at().toString());
        return changed(row);
    }

    /** Records a "wrong" judgement; answers the row. */
    synchronized Map<String, Object> wrong(String id, String reason) {
        Map<String, Object> row = row(id, "", "");
        row.put("wrong", reason);
        return changed(row);
    }

    /** Records that the person asked for the action to be stopped, and why; answers the row. */
    synchronized Map<String, Object> stopAsked(String id, String reason) {
        Map<String, Object> row = row(id, "", "");
        row.put("stop", reason);
        return changed(row);
    }

    /** Newest first. */
    synchronized List<Map<String, Object>> recent() {
        List<Map<String, Object>> out = new ArrayList<>();
        entries.values().forEach(r -> out.addFirst(snapshot(r)));
        return out;
    }

    /** Stamps a row that just changed with the next revision; answers a copy. */
    private Map<String, Object> changed(Map<String, Object> row) {
        row.put("rev", ++revision);
        return snapshot(row);
    }

    private static Map<String, Object> snapshot(Map<String, Object> row) {
        return Collections.unmodifiableMap(new LinkedHashMap<>(row));
    }

    private Map<String, Object> row(String id, String robot, String action) {
        Map<String, Object> row = entries.get(id);
        if (row == null) {
            row = new LinkedHashMap<>();
            row.put("id", id);
            row.put("robot", robot);
            row.put("action", action);
            row.put("args", Map.of());
            row.put("status", "sent");
            row.put("detail", "");
            row.put("at", Instant.now().toString());
            row.put("wrong", "");
            row.put("stop", "");
            entries.put(id, row);
            while (entries.size() > LIMIT) {
                entries.remove(entries.keySet().iterator().next());
            }
        } else {
            if (!robot.isEmpty()) {
                row.put("robot", robot);
            }
            if (!action.isEmpty()) {
                row.put("action", action);
            }
        }
        return row;
    }
}
