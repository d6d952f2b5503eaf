package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Map;
import org.junit.jupiter.api.Test;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

/**
 * Joins answered from a hash index: the look-up decides an equality condition by itself only where the index key
 * compares exactly, and numbers compare numerically ({@code -0.0 == 0}).
 */
class JoinIndexTest {

    /** {@code Same(mA: A, mB: B .v == mA.v)} over a float slot {@code v} in both classes. */
    private static Fixture floats() {
        Fixture f = new Fixture();
        f.kb.add(Frame.classFrame("A").slot(Slot.builder("v", DataType.FLOAT).build()).build());
        f.kb.add(Frame.classFrame("B").slot(Slot.builder("v", DataType.FLOAT).build()).build());
        f.kb.add(Frame.classFrame("Same").slot(Fixture.inst("mA", "A")).slot(Fixture.inst("mB", "B", ".v == mA.v"))
                .build());
        return f;
    }

    private static void reading(Fixture f, String name, String cls, double v) {
        f.kb.add(Frame.instance(name, cls).provenance(Provenance.RUNTIME)
                .slot(Slot.ofValue("v", DataType.FLOAT, Value.of(v))).build());
    }

    @Test
    void join_whenHugeFloatsShareAnIndexKey_testsTheConditionAndBindsOnlyTheEqualOne() {
        Fixture f = floats();
        InferenceEngine e = f.engine();
        reading(f, "a1", "A", 1e300);
        reading(f, "b1", "B", 1e301); // beyond a long: both fall under one index key
        assertThat(e.runToQuiescence()).isZero();

        reading(f, "b2", "B", 1e300);
        assertThat(e.runToQuiescence()).isEqualTo(1);
        assertThat(f.instancesOf("Same")).singleElement()
                .satisfies(i -> assertThat(f.kb.value(i, "mB")).contains(Value.ref("b2")));
    }

    @Test
    void join_whenMoreFactsShareAKeyThanAShortBucketHolds_findsEveryOneOfThem() {
        Fixture f = floats();
        InferenceEngine e = f.engine();
        for (int i = 0; i < 40; i++) { // past the eight of a short bucket (Bag.SMALL), which then becomes a set
            reading(f, "a" + i, "A", 7.0);
        }
        assertThat(e.runToQuiescence()).isZero();

        reading(f, "b1", "B", 7.0);

        assertThat(e.runToQuiescence()).isEqualTo(40);
    }

    @Test
    void join_whenOneSlotIsReadByTwoEqualityJoins_filesEachFactUnderBothKeys_andTakesItOutOfBoth() {
        Fixture f = new Fixture();
        f.kb.add(Frame.classFrame("A").slot(Slot.builder("x", DataType.INTEGER).build())
                .slot(Slot.builder("y", DataType.INTEGER).build()).build());
        f.kb.add(Frame.classFrame("B").slot(Slot.builder("x", DataType.INTEGER).build()).build());
        f.kb.add(Frame.classFrame("C").slot(Slot.builder("y", DataType.INTEGER).build()).build());
        f.kb.add(Frame.classFrame("R").slot(Fixture.inst("mA", "A")).slot(Fixture.inst("mB", "B", ".x == mA.x"))
                .slot(Fixture.inst("mC", "C", ".y == mA.y")).build()); // mA's memory: an index on x, one on y
        InferenceEngine e = f.engine();
        f.assertFact("a1", "A", "x", 1, "y", 5);
        f.assertFact("b1", "B", "x", 1);
        assertThat(e.runToQuiescence()).isZero();
        f.kb.remove("a1");
        assertThat(e.runToQuiescence()).isZero();

        f.assertFact("c1", "C", "y", 5); // finds mA's partners under y = 5: a1 has left that index too

        assertThat(e.runToQuiescence()).isZero();
        f.assertFact("a2", "A", "x", 1, "y", 5);
        assertThat(e.runToQuiescence()).isEqualTo(1);
        assertThat(f.instancesOf("R")).singleElement()
                .satisfies(i -> assertThat(f.kb.value(i, "mA")).contains(Value.ref("a2")));
    }

    @Test
    void join_whenNegativeZeroMeetsZero_holds_fromEitherSide() {
        Fixture f = floats();
        InferenceEngine e = f.engine();
        reading(f, "a1", "A", -0.0);
        reading(f, "b1", "B", 0.0);
        assertThat(e.runToQuiescence()).isEqualTo(1);

        reading(f, "b2", "B", -0.0);
        reading(f, "a2", "A", 0.0);
        assertThat(e.runToQuiescence()).isEqualTo(3);
        assertThat(f.instancesOf("Same")).hasSize(4);
    }

    @Test
    void join_whenFractionsAreEqualOrNot_bindsByValue() {
        Fixture f = floats();
        InferenceEngine e = f.engine();
        reading(f, "a1", "A", 0.25);
        reading(f, "b1", "B", 0.5);
        reading(f, "b2", "B", 0.25);
        assertThat(e.runToQuiescence()).isEqualTo(1);
        assertThat(f.kb.value(f.instancesOf("Same").getFirst(), "mB")).contains(Value.ref("b2"));
    }

    @Test
    void fire_whenAFrameAlreadyHasTheNextDerivedName_takesTheNextNameAndFires() {
        Fixture f = new Fixture();
        f.cls("Stimulus", null).cls("Thing", null);
        f.kb.add(Frame.classFrame("Echo").slot(Fixture.inst("mIn", "Stimulus")).build());
        f.assertFact("Echo-1", "Thing");
        InferenceEngine e = f.engine();
        f.assertFact("s1", "Stimulus");

        assertThat(e.runToQuiescence()).isEqualTo(1);

        assertThat(f.instancesOf("Echo")).singleElement().isNotEqualTo("Echo-1")
                .satisfies(i -> assertThat(f.kb.value(i, "mIn")).contains(Value.ref("s1")));
        assertThat(f.kb.require("Echo-1").parent()).contains("Thing");
        assertThat(f.trace).noneMatch(t -> t instanceof TraceEvent.Blocked);
    }

    @Test
    void join_afterANonReactiveSlotChanged_newFactsAreJoinedOnItsNewValue() {
        Fixture f = new Fixture();
        deliverByName(f);
        InferenceEngine e = f.engine();
        f.assertFact("u1", "User", "name", "Ann");
        e.runToQuiescence();
        f.kb.replace(f.kb.require("u1").withSlot(Fixture.str("name", "Eve"))); // not reactive: nothing is matched again
        e.runToQuiescence();

        f.assertFact("oAnn", "Order", "who", "Ann");
        f.assertFact("oEve", "Order", "who", "Eve");
        e.runToQuiescence();

        assertThat(f.instancesOf("Deliver")).as("u1 is called Eve now").singleElement()
                .satisfies(d -> assertThat(f.kb.value(d, "mOrder")).contains(Value.ref("oEve")));
    }

    @Test
    void constantCondition_afterANonReactiveSlotChanged_newPartnersMeetTheInstanceAsItIsNow() {
        Fixture f = new Fixture();
        adultTalk(f);
        InferenceEngine e = f.engine();
        f.assertFact("adult", "User", "age", 20L);
        f.assertFact("child", "User", "age", 10L);
        f.assertFact("m1", "Mouth");
        e.runToQuiescence();
        assertThat(f.instancesOf("Talk")).hasSize(1);
        f.kb.replace(f.kb.require("adult").withSlot(Fixture.num("age", 12)));
        f.kb.replace(f.kb.require("child").withSlot(Fixture.num("age", 19)));
        e.runToQuiescence();
        assertThat(f.instancesOf("Talk")).as("not reactive: what was derived stays, nothing fires").hasSize(1);

        f.assertFact("m2", "Mouth");
        e.runToQuiescence();

        assertThat(f.instancesOf("Talk").stream().filter(t -> f.kb.value(t, "mMouth").equals(java.util.Optional.of(
                Value.ref("m2")))).map(t -> f.kb.value(t, "mUser").orElseThrow())).as("only the user of 18 or more now")
                .containsExactly(Value.ref("child"));
    }

    @Test
    void waitingActivation_whenANonReactiveChangeMakesItsConditionFalse_doesNotFire_andOneStillTrueDoes() {
        Fixture f = new Fixture();
        adultTalk(f);
        InferenceEngine e = f.engine();
        f.assertFact("ann", "User", "age", 20L);
        f.assertFact("bob", "User", "age", 30L);
        f.assertFact("m1", "Mouth");
        assertThat(e.agendaSize()).as("both wait on the agenda").isEqualTo(2);

        f.kb.replace(f.kb.require("ann").withSlot(Fixture.num("age", 12)));
        f.kb.replace(f.kb.require("bob").withSlot(Fixture.num("age", 25)));

        assertThat(e.runToQuiescence()).isEqualTo(1);
        assertThat(f.instancesOf("Talk")).singleElement()
                .satisfies(t -> assertThat(f.kb.value(t, "mUser")).contains(Value.ref("bob")));
        assertThat(f.traced(TraceEvent.Blocked.class)).containsExactly(new TraceEvent.Blocked("Talk",
                Map.of("mUser", "ann", "mMouth", "m1"), "the condition of slot 'mUser' no longer holds: a bound "
                        + "instance changed while the binding waited on the agenda"));
        assertThat(f.traced(TraceEvent.FactChanged.class)).as("not reactive: nothing is matched again").isEmpty();
    }

    @Test
    void waitingActivation_whenANonReactiveChangeBreaksItsJoin_doesNotFire() {
        Fixture f = new Fixture();
        deliverByName(f);
        InferenceEngine e = f.engine();
        f.assertFact("u1", "User", "name", "Ann");
        f.assertFact("oAnn", "Order", "who", "Ann");
        assertThat(e.agendaSize()).isEqualTo(1);

        f.kb.replace(f.kb.require("u1").withSlot(Fixture.str("name", "Eve")));

        assertThat(e.runToQuiescence()).isZero();
        assertThat(f.instancesOf("Deliver")).isEmpty();
        assertThat(f.traced(TraceEvent.Blocked.class)).singleElement()
                .satisfies(b -> assertThat(b.reason()).startsWith("the condition of slot 'mOrder' no longer holds"));
    }

    @Test
    void waitingActivation_whenANonReactiveChangeMakesItsScriptConditionFalse_doesNotFire() {
        Fixture f = new Fixture();
        f.kb.add(Frame.classFrame("User").slot(Slot.builder("age", DataType.INTEGER).reactive(false).build()).build());
        f.kb.add(Frame.classFrame("Greet").slot(Fixture.inst("mUser", "User", "js: adult")).build());
        f.scripts.define("adult", g -> ((Number) ((Map<?, ?>) Fixture.view(g).get("mUser")).get("age")).longValue() >= 18);
        InferenceEngine e = f.engine();
        f.assertFact("ann", "User", "age", 20L);
        assertThat(e.agendaSize()).isEqualTo(1);

        f.kb.replace(f.kb.require("ann").withSlot(Fixture.num("age", 12)));

        assertThat(e.runToQuiescence()).isZero();
        assertThat(f.traced(TraceEvent.Blocked.class)).singleElement().satisfies(b -> assertThat(b.reason())
                .isEqualTo("the script condition of slot 'mUser' is false: a bound instance changed while the binding "
                        + "waited on the agenda"));
    }

    @Test
    void waitingActivation_whenANonReactiveChangeReachesItThroughAReference_doesNotFire() {
        Fixture f = new Fixture();
        f.kb.add(Frame.classFrame("Stim").slot(Slot.builder("key", DataType.INTEGER).reactive(false).build()).build());
        f.kb.add(Frame.classFrame("Target").slot(Slot.builder("key", DataType.INTEGER).build()).build());
        f.kb.add(Frame.classFrame("Holder").slot(Slot.builder("mS", DataType.INSTANCE).argument("Stim").build()).build());
        f.kb.add(Frame.classFrame("Far").slot(Fixture.inst("mH", "Holder"))
                .slot(Fixture.inst("mT", "Target", ".key == mH.mS.key")).build());
        InferenceEngine e = f.engine();
        f.assertFact("s1", "Stim", "key", 1L);
        f.assertFact("h1", "Holder", "mS", "@s1");
        f.assertFact("t1", "Target", "key", 1L);
        assertThat(e.agendaSize()).isEqualTo(1);

        f.kb.replace(f.kb.require("s1").withSlot(Fixture.num("key", 2)));

        assertThat(e.runToQuiescence()).as("Far read s1.key through h1; 2 != 1 now").isZero();
        assertThat(f.traced(TraceEvent.Blocked.class)).singleElement()
                .satisfies(b -> assertThat(b.reason()).startsWith("the condition of slot 'mT' no longer holds"));
    }

    /** User (a non-reactive name), Order (who) and Deliver joining an order to the user it names. */
    private static void deliverByName(Fixture f) {
        f.kb.add(Frame.classFrame("User").slot(Slot.builder("name", DataType.STRING).reactive(false).build()).build());
        f.kb.add(Frame.classFrame("Order").slot(Slot.builder("who", DataType.STRING).build()).build());
        f.kb.add(Frame.classFrame("Deliver").slot(Fixture.inst("mUser", "User"))
                .slot(Fixture.inst("mOrder", "Order", ".who == mUser.name")).build());
    }

    /** User (a non-reactive age), Mouth, and Talk binding a User of 18 or more to a Mouth. */
    private static void adultTalk(Fixture f) {
        f.kb.add(Frame.classFrame("User").slot(Slot.builder("age", DataType.INTEGER).reactive(false).build()).build());
        f.cls("Mouth", null);
        f.kb.add(Frame.classFrame("Talk").slot(Slot.builder("mUser", DataType.INSTANCE).argument("User").required(true)
                        .condition(org.kicnp.core.ConditionParser.parse(".age >= 18")).build())
                .slot(Slot.builder("mMouth", DataType.INSTANCE).argument("Mouth").required(true).build()).build());
    }
}
