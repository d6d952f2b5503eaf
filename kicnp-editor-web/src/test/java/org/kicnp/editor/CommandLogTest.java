package org.kicnp.editor;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Instant;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * Each change to a command's row is stamped with the log's change count ({@code rev}), so that a page can tell which
 * of two copies of a row is newer when an answer and a feedback event overtake each other.
 */
class CommandLogTest {
    private static CommandFeedback feedback(String id, CommandFeedback.Status status, String detail) {
        return new CommandFeedback(Instant.now(), id, "scout", "patrol", status, detail);
    }

    private static long rev(Map<String, Object> row) {
        return (Long) row.get("rev");
    }

    @Test
    void everyChange_stampsTheRowWithAHigherRev_andTheListShowsTheLast() {
        CommandLog log = new CommandLog();
        Map<String, Object> sent = log.sent("tele-1", "scout", "patrol", Map.of());
        Map<String, Object> started = log.feedback(feedback("tele-1", CommandFeedback.Status.STARTED, ""));
        Map<String, Object> other = log.sent("tele-2", "scout", "go_to", Map.of("x", "1"));
        Map<String, Object> stopAsked = log.stopAsked("tele-1", "enough");
        Map<String, Object> failed = log.feedback(feedback("tele-1", CommandFeedback.Status.FAILED, "cancelled: enough"));

        assertThat(rev(sent)).isLessThan(rev(started));
        assertThat(rev(started)).isLessThan(rev(other));
        assertThat(rev(other)).isLessThan(rev(stopAsked));
        assertThat(rev(stopAsked)).isLessThan(rev(failed));
        // the stop's answer, were it to arrive after the cancellation, is the older copy: it says started
        assertThat(stopAsked).containsEntry("status", "started").containsEntry("stop", "enough");
        assertThat(failed).containsEntry("status", "failed").containsEntry("stop", "enough");
        assertThat(log.recent().getFirst()).containsEntry("id", "tele-2");
        assertThat(log.recent().get(1)).containsEntry("rev", rev(failed)).containsEntry("status", "failed");
    }
}
