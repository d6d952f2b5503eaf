package org.kicnp.core;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.kicnp.core.TwinKnowledgeBases.assertSameState;
import static org.kicnp.core.TwinKnowledgeBases.kb;
import static org.kicnp.core.TwinKnowledgeBases.outcome;
import static org.kicnp.core.TwinKnowledgeBases.referred;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * {@link KnowledgeBase#addInstance} with a prepared {@link InstanceShape} must end exactly as adding the same frame
 * the general way does (a twin knowledge base {@linkplain KnowledgeBase#withoutShortCuts without short cuts}): the
 * same refusal, frames, indexes and revisions — for names of every form, values that are no references or name
 * removed, wrong or missing frames, shapes whose class or slots do not fit, and between them class edits that change
 * what a shape found (an argument retyped, a slot dropped, a class moved in the hierarchy).
 */
class InstanceShapeTest {
    private static final List<InstanceShape> SHAPES = List.of(
            InstanceShape.of("Pair", List.of("mA", "mB")),
            InstanceShape.of("Pair", List.of("mA", "mB")),
            InstanceShape.of("Pair", List.of("mB", "mA")),
            InstanceShape.of("Triple", List.of("mA", "mB", "mC")),
            InstanceShape.of("Pair", List.of("mA", "key")), // not an instance slot of Pair
            InstanceShape.of("Pair", List.of("mA", "extra")), // not a slot of Pair
            InstanceShape.of("Ghost", List.of("mA")), // no such class
            InstanceShape.of("inst", List.of("mA")), // an instance, not a class
            InstanceShape.of("StimA", List.of()));

    private static Change pairClass(String second) {
        return new Change.Add(Frame.classFrame("Pair").parent("Derived")
                .slot(Frames.instanceSlot("mA", "StimA")).slot(Frames.instanceSlot("mB", second)).build());
    }

    @Test
    void addInstance_ofRandomNamesValuesAndShapes_endsAsTheGeneralPath_acrossClassEdits() {
        long quickAdds = 0;
        for (long seed = 1; seed <= 40; seed++) {
            quickAdds += run(new Random(seed));
        }
        assertThat(quickAdds).as("adds the prepared shape made").isGreaterThan(300);
    }

    @Test
    void aPreparedAdd_makesTheFrameAnAddWouldMake_andIndexesIt() {
        KnowledgeBase kb = kb();
        InstanceShape pair = InstanceShape.of("Pair", List.of("mA", "mB"));
        long before = kb.plainAdds();

        Frame made = kb.addInstance(pair, "Pair-7", new Value[] {Value.ref("s1"), Value.ref("s2")}, kb.require("s1"));

        assertThat(kb.plainAdds()).isEqualTo(before + 1);
        assertThat(made).isEqualTo(Frame.instance("Pair-7", "Pair").provenance(Provenance.RUNTIME)
                .slot(Slot.builder("mA", DataType.INSTANCE).value(Value.ref("s1")).build())
                .slot(Slot.builder("mB", DataType.INSTANCE).value(Value.ref("s2")).build()).build());
        assertThat(kb.require("Pair-7")).isSameAs(made);
        assertThat(kb.instancesOf("Derived")).containsExactly(made);
        assertThat(kb.referrers("s2")).containsExactly("Pair-7");
        assertThat(kb.revision("Pair-7")).isEqualTo(kb.version());
    }

    @Test
    void theArraysOfAnAdd_areNotKept_soACallerMayFillThemAgain() {
        KnowledgeBase kb = kb();
        InstanceShape pair = InstanceShape.of("Pair", List.of("mA", "mB"));
        Value[] values = {Value.ref("s1"), Value.ref("s2")};
        Frame[] near = {kb.require("s1"), kb.require("s2")};

        Frame first = kb.addInstance(pair, "Pair-1", values, near);
        values[0] = Value.ref("s3");
        values[1] = Value.ref("s4");
        near[0] = kb.require("s3");
        near[1] = kb.require("s4");
        Frame second = kb.addInstance(pair, "Pair-2", values, near);
        values[0] = null;
        near[0] = null;

        assertThat(kb.require("Pair-1")).isSameAs(first);
        assertThat(first.ownSlot("mA").flatMap(Slot::value)).contains(Value.ref("s1"));
        assertThat(first.ownSlot("mB").flatMap(Slot::value)).contains(Value.ref("s2"));
        assertThat(second.ownSlot("mA").flatMap(Slot::value)).contains(Value.ref("s3"));
        assertThat(second.ownSlot("mB").flatMap(Slot::value)).contains(Value.ref("s4"));
        assertThat(kb.referrers("s2")).containsExactly("Pair-1");
        assertThat(kb.referrers("s4")).containsExactly("Pair-2");
    }

    @Test
    void aShapeWhoseArgumentChanged_isCheckedAgain_andAValueOfTheOldClassIsRefused() {
        KnowledgeBase kb = kb();
        InstanceShape pair = InstanceShape.of("Pair", List.of("mA", "mB"));
        kb.addInstance(pair, "Pair-1", new Value[] {Value.ref("s1"), Value.ref("s2")});
        kb.replace(kb.require("Pair").toBuilder().slot(Frames.instanceSlot("mB", "StimA")).build()); // mB: StimA now

        assertThatThrownBy(() -> kb.addInstance(pair, "Pair-2", new Value[] {Value.ref("s3"), Value.ref("s4")}))
                .isInstanceOf(BatchRejectedException.class).hasMessageContaining("s4");
        assertThat(kb.contains("Pair-2")).isFalse();
        kb.addInstance(pair, "Pair-3", new Value[] {Value.ref("s3"), Value.ref("s5")});
        assertThat(kb.contains("Pair-3")).isTrue();
    }

    @Test
    void of_refusesASlotNamedTwiceAndInvalidNames() {
        assertThatThrownBy(() -> InstanceShape.of("Pair", List.of("mA", "mA")))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("twice");
        assertThatThrownBy(() -> InstanceShape.of("a b", List.of("mA"))).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> InstanceShape.of("Pair", List.of("m A"))).isInstanceOf(IllegalArgumentException.class);
    }

    /** One random sequence of 80 steps on twin knowledge bases; returns how many adds the shape made. */
    private static long run(Random r) {
        KnowledgeBase quick = kb();
        KnowledgeBase general = kb().withoutShortCuts();
        long madeBySetUp = quick.plainAdds();
        List<Frame> removed = new ArrayList<>();
        for (int step = 0; step < 80; step++) {
            int what = r.nextInt(24);
            if (what == 0) {
                Change edit = switch (r.nextInt(4)) {
                    case 0 -> pairClass(r.nextBoolean() ? "StimA" : "StimB"); // mB retyped (or back)
                    case 1 -> new Change.Add(Frame.classFrame("Pair").parent("Derived") // mB dropped
                            .slot(Frames.instanceSlot("mA", "StimA")).build());
                    case 2 -> new Change.Add(Frame.classFrame("Note").parent("Thing")
                            .slot(Frames.str("text", "step " + step)).build());
                    default -> new Change.Add(Frame.classFrame("StimB").parent(r.nextBoolean() ? "Stim" : "Thing")
                            .build());
                };
                String a = outcome(() -> quick.put(((Change.Add) edit).frame()));
                String b = outcome(() -> general.put(((Change.Add) edit).frame()));
                assertThat(a).isEqualTo(b);
            } else if (what <= 3 && !quick.instancesOf("Thing").isEmpty()) {
                List<Frame> live = quick.instancesOf("Thing");
                Frame victim = live.get(r.nextInt(live.size()));
                String a = outcome(() -> quick.remove(victim.name()));
                String b = outcome(() -> general.remove(victim.name()));
                assertThat(a).isEqualTo(b);
                if (a.equals("done")) {
                    removed.add(victim);
                }
            } else {
                InstanceShape shape = SHAPES.get(r.nextInt(SHAPES.size()));
                String name = name(r, shape, quick);
                Value[] values = values(r, shape, quick);
                Frame[] referred = referred(r, quick, removed);
                String expected = outcome(() -> general.addInstance(shape, name, values, referred));
                String actual = outcome(() -> quick.addInstance(shape, name, values, referred));
                assertThat(actual).as("add of %s %s", shape, name).isEqualTo(expected);
                if (actual.equals("done")) { // the number a prepared add keeps in its frame is the name's
                    assertThat(NameTable.numberOf(quick.require(name))).as("number of %s", name)
                            .isEqualTo(NameTable.numberOf(name));
                }
            }
            assertSameState(quick, general);
        }
        return quick.plainAdds() - madeBySetUp;
    }

    /** Mostly the class's name, '-' and a number; else taken names, other forms, invalid names. */
    private static String name(Random r, InstanceShape shape, KnowledgeBase kb) {
        String c = shape.className();
        return switch (r.nextInt(14)) {
            case 0 -> kb.frames().get(r.nextInt(kb.frames().size())).name(); // taken
            case 1 -> c + "_" + r.nextInt(100);
            case 2 -> c + "-";
            case 3 -> c + "-x-" + r.nextInt(9);
            case 4 -> c + "-1234567890"; // more digits than a name's number holds
            case 5 -> "Triple-" + r.nextInt(50);
            case 6 -> c + "- " + r.nextInt(9);
            case 7 -> c + "-" + r.nextInt(9) + "-" + r.nextInt(9);
            case 8 -> c + "- x-" + r.nextInt(9); // digits after the last '-', but not a frame name
            default -> c + "-" + r.nextInt(60);
        };
    }

    /** Mostly live instances of the slot's class; else frames of other classes, classes, removed names, no refs. */
    private static Value[] values(Random r, InstanceShape shape, KnowledgeBase kb) {
        List<String> all = new ArrayList<>(kb.frames().stream().map(Frame::name).toList());
        all.add("Ghost");
        Value[] out = new Value[shape.templates().size()];
        for (int i = 0; i < out.length; i++) {
            String slot = shape.templates().get(i).name();
            String cls = switch (slot) {
                case "mA" -> "StimA";
                case "mB" -> "StimB";
                default -> "Stim";
            };
            List<Frame> fits = kb.instancesOf(cls);
            int how = r.nextInt(12);
            out[i] = how == 0 ? Value.of(7)
                    : how <= 2 || fits.isEmpty() ? Value.ref(all.get(r.nextInt(all.size())))
                    : Value.ref(fits.get(r.nextInt(fits.size())).name());
        }
        return out;
    }
}
