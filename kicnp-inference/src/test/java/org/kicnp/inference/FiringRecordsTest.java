package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.kicnp.core.Condition;
import org.kicnp.core.ConditionParser;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Slot;

/**
 * What a firing leaves behind, kept in the lean forms the engine uses per firing: the checked conditions (values
 * taken at firing, texts made when read) and the supports' lists of dependents (a firing's new instance added without
 * a search); and the facts' activation lists, which a taken activation leaves.
 */
class FiringRecordsTest {

    private static Rule rule(String frame, String... slots) {
        List<SlotPattern> required = new java.util.ArrayList<>();
        for (int i = 0; i < slots.length; i++) {
            required.add(new SlotPattern(i, slots[i], "C", Condition.ANY, "COND_ANY", true, true, false, false,
                    Set.of(), Optional.empty()));
        }
        return Rule.of(frame, 0, 1, 0, required, List.of(), Optional.empty());
    }

    /** A behavior frame {@code Deliver} (a user; an order of more than one cup) fired once: for u1 and o1 (2 cups). */
    private record Delivered(Fixture f, InferenceEngine e, String made) {
        static Delivered fire() {
            Fixture f = new Fixture();
            f.cls("User", null).cls("Order", null);
            f.kb.add(Frame.classFrame("Deliver").slot(Fixture.inst("mUser", "User"))
                    .slot(Fixture.inst("mOrder", "Order", ".cups > 1")).build());
            InferenceEngine e = f.engine();
            f.assertFact("o1", "Order", "cups", 2);
            f.assertFact("u1", "User");
            e.runToQuiescence();
            String made = f.instancesOf("Deliver").getFirst();
            return new Delivered(f, e, made);
        }
    }

    @Test
    void checkedConditions_withAnOptionalSlotLeftEmptyBeforeABoundOne_nameEachBoundSlotWithItsConditionAndValue() {
        Fixture f = new Fixture();
        f.cls("User", null).cls("Camera", null).cls("Mic", null);
        f.kb.add(Frame.classFrame("Watch").slot(Fixture.inst("mUser", "User"))
                .slot(Slot.builder("mCam", DataType.INSTANCE).argument("Camera").build())
                .slot(Slot.builder("mMic", DataType.INSTANCE).argument("Mic")
                        .condition(ConditionParser.parse(".level > 3")).build()).build());
        InferenceEngine e = f.engine();
        f.assertFact("mic", "Mic", "level", 5);
        f.assertFact("u1", "User");
        e.runToQuiescence();

        Derivation d = e.derivation(f.instancesOf("Watch").getFirst()).orElseThrow();

        assertThat(d.binding()).containsOnlyKeys("mUser", "mMic");
        assertThat(d.conditions()).containsExactly(new Derivation.CheckedCondition("mUser", "COND_ANY", "u1"),
                new Derivation.CheckedCondition("mMic", ".level > 3", "5"));
        assertThatThrownBy(() -> d.conditions().add(d.conditions().getFirst()))
                .isInstanceOf(UnsupportedOperationException.class);
    }

    @Test
    void checkedConditions_afterTheTestedValueChanges_stillGiveTheValueTestedWhenTheFrameFired() {
        Delivered run = Delivered.fire();
        Fixture f = run.f();
        InferenceEngine e = run.e();
        String made = run.made();

        f.kb.replace(f.kb.require("o1").withSlot(Fixture.num("cups", 3))); // still more than one: the instance stays
        e.runToQuiescence();

        assertThat(f.instancesOf("Deliver")).containsExactly(made);
        assertThat(e.derivation(made).orElseThrow().conditions()).extracting(Derivation.CheckedCondition::value)
                .containsExactly("u1", "2");
    }

    /**
     * A firing keeps only the values its conditions read along a path (none, one, or several) and takes the others
     * from its binding: whichever it is, the list names every bound slot, in slot order, with what it was tested on.
     */
    @Test
    void checkedConditions_withNoneOneOrSeveralConditionsReadingAPath_listEverySlotInOrderWithTheValueTested() {
        Fixture f = new Fixture();
        f.cls("User", null).cls("Room", null).cls("Order", null);
        f.kb.add(Frame.classFrame("Greet").slot(Fixture.inst("mUser", "User"))
                .slot(Fixture.inst("mRoom", "Room")).build());
        f.kb.add(Frame.classFrame("Serve").slot(Fixture.inst("mUser", "User", ".age > 1"))
                .slot(Fixture.inst("mRoom", "Room")).slot(Fixture.inst("mOrder", "Order", ".cups > 1")).build());
        InferenceEngine e = f.engine();
        f.assertFact("u1", "User", "age", 30);
        f.assertFact("r1", "Room");
        f.assertFact("o1", "Order", "cups", 2);
        e.runToQuiescence();

        Derivation greet = e.derivation(f.instancesOf("Greet").getFirst()).orElseThrow();
        Derivation serve = e.derivation(f.instancesOf("Serve").getFirst()).orElseThrow();

        assertThat(greet.conditions()).containsExactly(new Derivation.CheckedCondition("mUser", "COND_ANY", "u1"),
                new Derivation.CheckedCondition("mRoom", "COND_ANY", "r1"));
        assertThat(serve.conditions()).containsExactly(new Derivation.CheckedCondition("mUser", ".age > 1", "30"),
                new Derivation.CheckedCondition("mRoom", "COND_ANY", "r1"),
                new Derivation.CheckedCondition("mOrder", ".cups > 1", "2"));
        assertThat(new Derivation(serve.instance(), "Serve", serve.binding(), List.copyOf(serve.conditions()),
                serve.firing(), serve.trigger(), Optional.empty())).isEqualTo(serve).hasSameHashCodeAs(serve);
    }

    @Test
    void derivation_ofAFiring_isAValueEqualToOneMadeFromItsParts_inSlotOrder_andReadOnly() {
        Delivered run = Delivered.fire();
        InferenceEngine e = run.e();
        String made = run.made();

        Derivation d = e.derivation(made).orElseThrow();
        Derivation fromParts = new Derivation(made, "Deliver", new LinkedHashMap<>(d.binding()),
                new ArrayList<>(d.conditions()), d.firing(), "u1", Optional.empty());

        assertThat(d.binding()).containsExactly(Map.entry("mUser", "u1"), Map.entry("mOrder", "o1"));
        assertThat(d.conditions()).containsExactly(new Derivation.CheckedCondition("mUser", "COND_ANY", "u1"),
                new Derivation.CheckedCondition("mOrder", ".cups > 1", "2"));
        assertThat(d.trigger()).isEqualTo("u1");
        assertThat(fromParts).isEqualTo(d).hasSameHashCodeAs(d).hasToString(d.toString());
        assertThat(d.toString()).isEqualTo("Derivation[instance=" + made + ", frame=Deliver, binding={mUser=u1, "
                + "mOrder=o1}, conditions=" + d.conditions() + ", firing=" + d.firing()
                + ", trigger=u1, createdBy=Optional.empty]");
        assertThat(new Derivation(made, "Deliver", d.binding(), d.conditions(), d.firing() + 1, "u1",
                Optional.empty())).isNotEqualTo(d);
        assertThat(new Derivation(made, "Deliver", Map.of("mUser", "u1"), d.conditions(), d.firing(), "u1",
                Optional.empty())).isNotEqualTo(d);
        assertThatThrownBy(() -> d.binding().put("mUser", "u2")).isInstanceOf(UnsupportedOperationException.class);
        assertThatThrownBy(() -> d.conditions().set(0, null)).isInstanceOf(UnsupportedOperationException.class);
        assertThat(e.derivation(made).orElseThrow().binding()).containsEntry("mUser", "u1");
    }

    @Test
    void supports_aFiringsInstance_isListedOnceUnderEachSupport_andLeavesEveryListWhenReleased() {
        KnowledgeBase kb = KnowledgeBase.create();
        FactView facts = new FactView(kb);
        Supports supports = new Supports(facts);
        Rule r = rule("R", "mA", "mB");
        FactView.Fact[] refs = {facts.touch("a"), facts.touch("b")};
        Derivation d = new Derivation("R-1", "R", Activation.bindingOf(r, new String[] {"a", "b"}), List.of(), 1, "b",
                Optional.empty());

        supports.record(d, r, refs, 1);
        supports.record(new Derivation("R-2", "R", Activation.bindingOf(r, new String[] {"a", "c"}), List.of(), 2,
                "c", Optional.empty()), r, new FactView.Fact[] {refs[0], facts.touch("c")}, 2);

        assertThat(supports.dependentsOf("a")).containsExactly("R-1", "R-2");
        assertThat(supports.dependentsOf("b")).containsExactly("R-1");
        supports.release("R-1");
        assertThat(supports.dependentsOf("a")).containsExactly("R-2");
        assertThat(supports.dependentsOf("b")).isEmpty();
        assertThat(supports.closure("a")).containsExactly("R-2");
    }

    @Test
    void agenda_anActivationTaken_leavesItsFactsLists_andTheNextOneWithThoseFactsIsFoundAndWithdrawn() {
        KnowledgeBase kb = KnowledgeBase.create();
        FactView facts = new FactView(kb);
        Agenda agenda = new Agenda(facts);
        Rule r = rule("R", "mA", "mB");
        FactView.Fact[] refs = {facts.touch("a"), facts.touch("b")};
        String[] bound = {"a", "b"};
        BindingKey key = new BindingKey("R", bound);
        agenda.add(new Activation(r, bound, refs, 2, 1, key));

        Activation first = agenda.poll();

        assertThat(first).isNotNull();
        assertThat(agenda.contains(key, refs)).as("a taken activation is no longer waiting").isFalse();
        assertThat(refs[0].activations).isNull();

        Activation again = new Activation(r, bound, refs, 2, 2, key); // the binding matched again, say
        agenda.add(again);
        assertThat(agenda.contains(key, refs)).isTrue();
        assertThat(refs[1].activations()).containsExactly(again);
        agenda.withdrawFact("a");
        assertThat(agenda.size()).isZero();
        assertThat(agenda.poll()).isNull();
        assertThat(agenda.contains(key, refs)).isFalse();
    }
}
