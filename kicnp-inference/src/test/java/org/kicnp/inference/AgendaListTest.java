package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.kicnp.core.Frame;

/** {@link InferenceEngine#agenda()}: the waiting activations, in firing order, as a read-only copy. */
class AgendaListTest {

    private static Fixture twoPriorities() {
        Fixture f = new Fixture();
        f.cls("Stimulus", null);
        f.kb.add(Frame.classFrame("Low").slot(Fixture.inst("mIn", "Stimulus")).build());
        f.kb.add(Frame.classFrame("High").priority(5).slot(Fixture.inst("mIn", "Stimulus")).build());
        return f;
    }

    @Test
    void agenda_whenTwoFramesMatch_listsThemInFiringOrderWithBindingAndPriority() {
        Fixture f = twoPriorities();
        InferenceEngine e = f.engine();
        assertThat(e.agenda()).isEmpty();
        f.assertFact("s1", "Stimulus");

        List<AgendaEntry> agenda = e.agenda();

        assertThat(agenda).extracting(AgendaEntry::frame).containsExactly("High", "Low");
        assertThat(agenda.getFirst().binding()).isEqualTo(Map.of("mIn", "s1"));
        assertThat(agenda.getFirst().priority()).isEqualTo(5);
        assertThat(agenda.get(1).priority()).isZero();
        assertThat(agenda.getFirst().recency()).isPositive();
        assertThat(e.agendaSize()).isEqualTo(2);
    }

    @Test
    void agenda_afterTheEngineRuns_isEmpty_whileAnEarlierCopyIsUnchanged() {
        Fixture f = twoPriorities();
        InferenceEngine e = f.engine();
        f.assertFact("s1", "Stimulus");
        List<AgendaEntry> before = e.agenda();

        assertThat(e.runToQuiescence()).isEqualTo(2);

        assertThat(e.agenda()).isEmpty();
        assertThat(before).hasSize(2);
    }
}
