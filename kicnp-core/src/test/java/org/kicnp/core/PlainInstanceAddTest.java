package org.kicnp.core;

import static org.assertj.core.api.Assertions.assertThat;
import static org.kicnp.core.TwinKnowledgeBases.assertSameState;
import static org.kicnp.core.TwinKnowledgeBases.kb;
import static org.kicnp.core.TwinKnowledgeBases.outcome;
import static org.kicnp.core.TwinKnowledgeBases.referred;
import static org.kicnp.core.TwinKnowledgeBases.stimulus;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Adds and batches of adds of plain instances (stimuli, derived instances) take a short cut ({@link PlainInstanceAdd});
 * whatever they are given, they must end exactly as the general path does (a twin knowledge base made
 * {@link KnowledgeBase#withoutShortCuts without short cuts}): the same refusal, the same frames, indexes and
 * revisions. Checked on random frames of every shape near the plain one (wrong classes, missing or removed targets,
 * undeclared or mistyped slots, durable frames, parts, links, own arguments, taken names, names twice in a batch,
 * references into the same batch), with random removals and class edits between them.
 */
class PlainInstanceAddTest {
    private static final List<String> NAMES = List.of("P1", "P2", "P3", "P4", "P5", "P6", "s1", "Pair");
    private static final List<String> PARENTS = List.of("Pair", "Pair", "Pair", "Triple", "Triple", "Derived", "StimA",
            "StimA", "StimB", "Thing", "inst", "Ghost");
    private static final List<String> SLOTS = List.of("mA", "mB", "mC", "key", "extra");

    @Test
    void add_ofRandomFramesNearThePlainShape_endsAsTheGeneralPath() {
        long plain = 0;
        for (long seed = 1; seed <= 40; seed++) {
            plain += run(new Random(seed));
        }
        // Most candidates are plain and valid; the short cut must have served a good share of them.
        assertThat(plain).as("adds the short cut made").isGreaterThan(200);
    }

    @Test
    void add_ofPlainInstances_takesTheShortCut_evenBeforeAnyBatchHasCheckedTheirClasses() {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.apply(kb().frames().stream().filter(Frame::isClass).map(f -> (Change) new Change.Add(f)).toList());
        kb.apply(List.of(new Change.Add(stimulus("s1", "StimA")), new Change.Add(stimulus("s2", "StimB")),
                new Change.Add(stimulus("s3", "StimA")), new Change.Add(stimulus("s4", "StimB"))));
        kb.add(pair("P1", "s1", "s2"));
        kb.add(pair("P2", "s3", "s4"), kb.require("s3"), kb.require("s4"));
        assertThat(kb.plainAdds()).isEqualTo(6);
        assertThat(kb.instancesOf("Derived")).extracting(Frame::name).containsExactly("P1", "P2");
        assertThat(kb.instancesOf("Stim")).extracting(Frame::name).containsExactly("s1", "s2", "s3", "s4");
        assertThat(kb.children("Pair")).extracting(Frame::name).containsExactly("Triple", "P1", "P2");
        assertThat(kb.referrers("s3")).containsExactly("P2");
        assertThat(kb.revision("P2")).isEqualTo(kb.version());
    }

    private static Frame pair(String name, String a, String b) {
        return Frame.instance(name, "Pair").provenance(Provenance.RUNTIME)
                .slot(Slot.builder("mA", DataType.INSTANCE).value(Value.ref(a)).build())
                .slot(Slot.builder("mB", DataType.INSTANCE).value(Value.ref(b)).build()).build();
    }

    /** One random sequence of 80 steps on twin knowledge bases; returns how many adds took the short cut. */
    private static long run(Random r) {
        KnowledgeBase quick = kb();
        KnowledgeBase general = kb().withoutShortCuts();
        long madeBySetUp = general.plainAdds();
        List<Frame> removed = new ArrayList<>();
        for (int step = 0; step < 80; step++) {
            int what = r.nextInt(20);
            if (what == 0) {
                // a class edit: the knowledge base forgets what it knew of its classes
                Frame note = Frame.classFrame("Note").parent("Thing")
                        .slot(Frames.str("text", "step " + step)).build();
                for (KnowledgeBase kb : List.of(quick, general)) {
                    kb.put(note);
                }
            } else if (what <= 2 && !quick.instancesOf("Thing").isEmpty()) {
                List<Frame> live = quick.instancesOf("Thing");
                Frame victim = live.get(r.nextInt(live.size()));
                String a = outcome(() -> quick.remove(victim.name()));
                String b = outcome(() -> general.remove(victim.name()));
                assertThat(a).isEqualTo(b);
                if (a.equals("done")) {
                    removed.add(victim);
                }
            } else if (what <= 12) {
                Frame f = candidate(r, quick, List.of());
                Frame[] referred = referred(r, quick, removed);
                String expected = outcome(() -> general.add(f, referred));
                String actual = outcome(() -> quick.add(f, referred));
                assertThat(actual).as("add of %s", f).isEqualTo(expected);
            } else {
                List<Change> batch = new ArrayList<>();
                List<String> inBatch = new ArrayList<>();
                for (int i = 1 + r.nextInt(5); i > 0; i--) {
                    Frame f = candidate(r, quick, inBatch);
                    batch.add(new Change.Add(f));
                    inBatch.add(f.name());
                }
                String expected = outcome(() -> general.apply(batch));
                String actual = outcome(() -> quick.apply(batch));
                assertThat(actual).as("batch %s", batch).isEqualTo(expected);
            }
            assertSameState(quick, general);
        }
        assertThat(general.plainAdds()).isEqualTo(madeBySetUp);
        return quick.plainAdds() - madeBySetUp;
    }

    /** A frame near the plain shape; {@code inBatch}: names of frames before it in its batch, which it may name. */
    private static Frame candidate(Random r, KnowledgeBase kb, List<String> inBatch) {
        String parent = pick(r, PARENTS);
        String name = pick(r, NAMES) + (r.nextInt(4) == 0 ? "" : "_" + r.nextInt(1000));
        if (!inBatch.isEmpty() && r.nextInt(10) == 0) {
            name = pick(r, inBatch); // twice in one batch
        }
        Frame.Builder b = Frame.instance(name.equals(parent) ? name + "_0" : name, parent)
                .provenance(r.nextInt(12) == 0 ? Provenance.DECLARED : Provenance.RUNTIME);
        List<String> slots = new ArrayList<>(switch (parent) {
            case "Triple" -> List.of("mA", "mB", "mC");
            case "StimA", "StimB" -> List.of("key");
            default -> List.of("mA", "mB");
        });
        if (r.nextInt(6) == 0) {
            slots.add(pick(r, SLOTS));
        }
        if (r.nextInt(8) == 0) {
            slots.remove(r.nextInt(slots.size()));
        }
        List<String> targets = new ArrayList<>(kb.instancesOf("Thing").stream().map(Frame::name).toList());
        targets.addAll(List.of("Ghost", "Pair", "StimA", "inst"));
        targets.addAll(inBatch);
        for (String s : slots.stream().distinct().toList()) {
            int shape = r.nextInt(28);
            Slot.Builder sb = switch (shape) {
                case 0 -> Slot.builder(s, DataType.INTEGER).value(Value.of(7));
                case 1 -> Slot.builder(s, DataType.INSTANCE).value(Value.ref(pick(r, targets))).argument("Stim");
                case 2 -> Slot.builder(s, DataType.INSTANCE).defaultValue(Value.ref(pick(r, targets)));
                case 3 -> Slot.builder(s, DataType.LIST).value(new Value.Lst(List.of(Value.ref(pick(r, targets)))));
                case 4 -> Slot.builder(s, DataType.INSTANCE).value(Value.ref(pick(r, targets)))
                        .condition(ConditionParser.parse(".key == 1"));
                case 5 -> Slot.builder(s, DataType.STRING).value(Value.of("text"));
                case 6 -> Slot.builder(s, DataType.BOOLEAN).value(Value.of(true));
                case 7 -> Slot.builder(s, DataType.FLOAT).value(Value.of(0.5));
                case 8 -> Slot.builder(s, DataType.INTEGER).defaultValue(Value.of(3));
                case 9 -> Slot.builder(s, DataType.INTEGER);
                default -> s.equals("key") || s.equals("extra")
                        ? Slot.builder(s, DataType.INTEGER).value(Value.of(r.nextInt(3)))
                        : Slot.builder(s, DataType.INSTANCE).value(Value.ref(
                                r.nextInt(3) == 0 ? pick(r, targets) : plausible(r, kb, s)));
            };
            b.slot(sb.build());
        }
        if (r.nextInt(15) == 0) {
            b.part("s1");
        }
        if (r.nextInt(15) == 0) {
            b.linkTo(Relation.Coordination.SUCCESSION, "Pair");
        }
        return b.build();
    }

    /** A live instance of the class slot {@code s} asks for, where there is one. */
    private static String plausible(Random r, KnowledgeBase kb, String s) {
        String cls = switch (s) {
            case "mA" -> "StimA";
            case "mB" -> "StimB";
            default -> "Stim";
        };
        List<Frame> fits = kb.instancesOf(cls);
        return fits.isEmpty() ? "Ghost" : fits.get(r.nextInt(fits.size())).name();
    }

    private static String pick(Random r, List<String> from) {
        return from.get(r.nextInt(from.size()));
    }
}
