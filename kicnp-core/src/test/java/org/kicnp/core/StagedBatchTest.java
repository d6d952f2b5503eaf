package org.kicnp.core;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.catchThrowableOfType;
import static org.kicnp.core.Frames.cls;
import static org.kicnp.core.Frames.figure1;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

class StagedBatchTest {

    @Test
    void commit_ofPartsWhereAChildComesBeforeItsParent_addsEverythingInOrder() {
        KnowledgeBase kb = figure1();
        StagedBatch batch = kb.stagedBatch();

        batch.add(List.of(Frame.instance("bob", "Visitor").build(), cls("Visitor", "Guest")));
        batch.add(List.of(cls("Guest", "User")));
        assertThat(kb.contains("bob")).isFalse();
        ChangeSet cs = batch.commit();

        assertThat(cs.events()).extracting(FrameEvent::name).containsExactly("bob", "Visitor", "Guest");
        assertThat(kb.instancesOf("User")).extracting(Frame::name).containsExactly("bob");
        assertThat(kb.isA("bob", "System")).isTrue();
    }

    @Test
    void commit_whenALaterPartGivesAnInstanceASubFrame_reportsBothAndAddsNothing() {
        KnowledgeBase kb = figure1();
        StagedBatch batch = kb.stagedBatch();
        batch.add(List.of(Frame.instance("ken", "KnownUser").build()));
        batch.add(List.of(cls("Sub", "ken")));

        assertThatThrownBy(batch::commit)
                .isInstanceOf(BatchRejectedException.class)
                .hasMessageContaining("Frame 'ken' cannot be an instance: it has sub-frames 'Sub'.")
                .hasMessageContaining("Frame 'Sub' is a kind of 'ken', which is an instance");
        assertThat(kb.contains("ken")).isFalse();
        assertThat(kb.version()).isEqualTo(1);
    }

    @Test
    void commit_whenALaterPartCompletesAChainAbove_checksSlotsAgainstTheWholeChain() {
        KnowledgeBase kb = figure1();
        StagedBatch batch = kb.stagedBatch();
        batch.add(List.of(cls("Mid", "Top"), Frame.classFrame("Leaf").parent("Mid")
                .slot(Slot.builder("speed", DataType.STRING).build()).build()));
        batch.add(List.of(Frame.classFrame("Top").parent("User")
                .slot(Slot.builder("speed", DataType.INTEGER).build()).build()));

        assertThatThrownBy(batch::commit)
                .isInstanceOf(BatchRejectedException.class)
                .hasMessage("Slot 'speed' of frame 'Leaf' is TYPE_STR but 'Top' declares it TYPE_INT.");
    }

    @Test
    void commit_afterTheKnowledgeBaseChangedBetweenParts_checksAgainstItAsItIsNow() {
        KnowledgeBase kb = figure1();
        StagedBatch batch = kb.stagedBatch();
        batch.add(List.of(Frame.instance("ken", "KnownUser").build()));

        kb.apply(List.of(new Change.Remove("KnownUser")));
        batch.add(List.of(Frame.instance("ann", "NewUser").build()));

        assertThatThrownBy(batch::commit)
                .isInstanceOf(BatchRejectedException.class)
                .hasMessage("Frame 'ken' is a kind of 'KnownUser', which is not defined.");
        assertThat(kb.contains("ann")).isFalse();
    }

    @Test
    void commit_twice_isRefused() {
        KnowledgeBase kb = figure1();
        StagedBatch batch = kb.stagedBatch();
        batch.add(List.of(cls("Guest", "User")));
        batch.commit();

        assertThatThrownBy(batch::commit).isInstanceOf(IllegalStateException.class)
                .hasMessageContaining("committed already");
        assertThatThrownBy(() -> batch.add(List.of(cls("Other", "User")))).isInstanceOf(IllegalStateException.class);
    }

    /** Random batches with mistakes of every kind, split at random: the outcome must be exactly apply's. */
    @Test
    void commit_ofRandomBatchesInRandomParts_givesExactlyWhatApplyGives() {
        Random random = new Random(11);
        int rejected = 0;
        for (int trial = 0; trial < 400; trial++) {
            List<Frame> frames = randomFrames(random);
            KnowledgeBase applied = withKim();
            KnowledgeBase stagedKb = withKim();
            StagedBatch batch = stagedKb.stagedBatch();
            for (int from = 0; from < frames.size(); ) {
                int to = Math.min(frames.size(), from + 1 + random.nextInt(4));
                batch.add(frames.subList(from, to));
                from = to;
            }
            List<Change> adds = frames.stream().<Change>map(Change.Add::new).toList();
            BatchRejectedException expected = catchThrowableOfType(BatchRejectedException.class,
                    () -> applied.apply(adds));
            BatchRejectedException actual = catchThrowableOfType(BatchRejectedException.class, batch::commit);

            if (expected == null) {
                assertThat(actual).as("trial %d", trial).isNull();
            } else {
                rejected++;
                assertThat(actual).as("trial %d", trial).isNotNull();
                assertThat(actual.problems()).as("trial %d", trial).isEqualTo(expected.problems());
            }
            assertThat(stagedKb.frames()).as("trial %d", trial).isEqualTo(applied.frames());
            assertSameIndexes(stagedKb, applied);
        }
        assertThat(rejected).as("rejected trials").isBetween(50, 350);
    }

    private static final String[] NAMES = {"A", "B", "C", "D", "E", "F", "G", "H"};
    private static final String[] PARENTS = {"A", "B", "C", "User", "User", "System", "KnownUser", "Nope", "D", "User", "kim"};

    /** Children, instances, revisions and referrers (seen through a removal that is bound to be rejected) agree. */
    private static void assertSameIndexes(KnowledgeBase actual, KnowledgeBase expected) {
        for (Frame f : expected.frames()) {
            String name = f.name();
            assertThat(actual.children(name)).as(name).isEqualTo(expected.children(name));
            assertThat(actual.instancesOf(name)).as(name).isEqualTo(expected.instancesOf(name));
            assertThat(actual.revision(name)).as(name).isEqualTo(expected.revision(name));
            List<Change> doomed = List.of(new Change.Remove(name), new Change.Add(cls("Doomed", "Nope")));
            assertThat(catchThrowableOfType(BatchRejectedException.class, () -> actual.apply(doomed)).problems())
                    .as(name).isEqualTo(catchThrowableOfType(BatchRejectedException.class,
                            () -> expected.apply(doomed)).problems());
        }
    }

    private static KnowledgeBase withKim() {
        KnowledgeBase kb = figure1();
        kb.add(Frame.instance("kim", "KnownUser").build());
        return kb;
    }

    /** Up to eight frames, names mostly distinct, parents and references mostly defined (in the batch or before). */
    private static List<Frame> randomFrames(Random random) {
        List<String> names = new ArrayList<>(List.of(NAMES));
        java.util.Collections.shuffle(names, random);
        List<Frame> out = new ArrayList<>();
        int count = 1 + random.nextInt(8);
        for (int i = 0; i < count; i++) {
            String name = random.nextInt(20) == 0 ? names.get(0) : names.get(i);
            String parent = random.nextInt(10) < 7 ? "User" : PARENTS[random.nextInt(PARENTS.length)];
            if (name.equals(parent)) {
                parent = "User";
            }
            Frame.Builder b = random.nextInt(3) == 0 ? Frame.instance(name, parent) : Frame.classFrame(name).parent(parent);
            if (random.nextBoolean()) {
                Slot.Builder s = Slot.builder("peer", DataType.INSTANCE)
                        .argument(random.nextInt(4) == 0 ? PARENTS[random.nextInt(PARENTS.length)] : "User");
                if (random.nextBoolean()) {
                    s.value(Value.ref(random.nextInt(3) > 0 ? "kim" : names.get(random.nextInt(names.size()))));
                }
                b.slot(s.build());
            }
            if (random.nextInt(6) == 0) {
                b.slot(Slot.builder("name", random.nextBoolean() ? DataType.STRING : DataType.INTEGER).build());
            }
            out.add(b.build());
        }
        return out;
    }
}
