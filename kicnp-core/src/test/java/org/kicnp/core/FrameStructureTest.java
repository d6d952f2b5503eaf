package org.kicnp.core;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A frame's parts and semantic links: read back as built, kept through {@link Frame#toBuilder()}, and part of the
 * frame's value — two frames that differ only there are different frames.
 */
class FrameStructureTest {
    private static final Relation SYNC = Relation.Coordination.SYNCHRONIZATION;
    private static final Relation AFTER = Relation.Coordination.SUCCESSION;

    private static Frame.Builder robot() {
        return Frame.classFrame("Robovie").parent("Robot")
                .slot(Slot.builder("name", DataType.STRING).build());
    }

    @Test
    void partsAndLinks_readBackAsBuilt_andSurviveToBuilder() {
        Frame f = robot().part("Head").part("Arm").linkTo(SYNC, "Pino").linkFrom(AFTER, "Greet").build();

        assertThat(f.parts()).containsExactly("Head", "Arm");
        assertThat(f.linksTo()).containsExactly(new SemanticLink(SYNC, "Pino"));
        assertThat(f.linksFrom()).containsExactly(new SemanticLink(AFTER, "Greet"));
        Frame again = f.toBuilder().build();
        assertThat(again).isEqualTo(f).hasSameHashCodeAs(f);
        assertThat(again.parts()).containsExactly("Head", "Arm");
        assertThat(f.withSlot(Slot.builder("age", DataType.INTEGER).build()).linksTo())
                .containsExactly(new SemanticLink(SYNC, "Pino"));
    }

    @Test
    void framesDifferingOnlyInPartsOrLinks_areNotEqual() {
        Frame plain = robot().build();
        List<Frame> others = List.of(
                robot().part("Head").build(),
                robot().linkTo(SYNC, "Pino").build(),
                robot().linkFrom(SYNC, "Pino").build(),
                robot().linkTo(AFTER, "Pino").build(),
                robot().linkTo(SYNC, "Scout").build());
        assertThat(robot().build()).isEqualTo(plain);
        for (Frame other : others) {
            assertThat(other).as("%s with %s %s %s", other, other.parts(), other.linksTo(), other.linksFrom())
                    .isNotEqualTo(plain);
        }
        for (int i = 0; i < others.size(); i++) {
            for (int j = 0; j < others.size(); j++) {
                assertThat(others.get(i).equals(others.get(j))).as("%d vs %d", i, j).isEqualTo(i == j);
            }
        }
        assertThat(plain.parts()).isEmpty();
        assertThat(plain.linksTo()).isEmpty();
        assertThat(plain.linksFrom()).isEmpty();
    }
}
