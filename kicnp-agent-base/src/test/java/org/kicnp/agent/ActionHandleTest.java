package org.kicnp.agent;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.kicnp.protocol.FeedbackStage;
import org.kicnp.protocol.Message.Command;
import org.kicnp.protocol.Message.Feedback;

class ActionHandleTest {
    private final List<Feedback> sent = new ArrayList<>();
    private final ActionHandle handle = new ActionHandle(new Command("c1", "scout", "walk", Map.of()), sent::add);

    @Test
    void reports_areSentInOrder_asFeedbackForTheCommand() {
        handle.started();
        handle.progress(0.5, "halfway");
        handle.ended("arrived");
        assertThat(sent).containsExactly(
                new Feedback("c1", "scout", FeedbackStage.STARTED, Optional.empty(), ""),
                new Feedback("c1", "scout", FeedbackStage.PROGRESS, Optional.of(0.5), "halfway"),
                new Feedback("c1", "scout", FeedbackStage.ENDED, Optional.empty(), "arrived"));
        assertThat(handle.isDone()).isTrue();
    }

    @Test
    void secondEnd_isRefused() {
        handle.failed("blocked");
        assertThatThrownBy(() -> handle.ended("arrived")).isInstanceOf(IllegalStateException.class)
                .hasMessage("Command 'c1' was already reported as done.");
        assertThat(sent).hasSize(1);
    }

    @Test
    void progressAfterEnd_isRefused() {
        handle.ended("arrived");
        assertThatThrownBy(() -> handle.progress(1.0, "late")).isInstanceOf(IllegalStateException.class)
                .hasMessage("Command 'c1' is done; no more progress reports.");
    }
}
