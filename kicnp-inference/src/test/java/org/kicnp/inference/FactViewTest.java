package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

/**
 * {@link FactView#follow} steps from fact to fact through the references it resolved once; it must read exactly what
 * {@link Conditions#follow(Value, List)} reads by name, whatever happened to the facts since. And a fact's memberships
 * of alpha memories, one held as itself and more as an array, are found, left and taken out alike.
 */
class FactViewTest {
    private final Fixture f = new Fixture();
    private final FactView facts = new FactView(f.kb);
    private final Conditions conditions = new Conditions(facts);

    private static final List<List<String>> PATHS = List.of(List.of(), List.of("key"), List.of("mS"),
            List.of("mS", "key"), List.of("mH", "mS", "key"), List.of("mH", "mS"), List.of("mH", "nope", "key"),
            List.of("key", "key"), List.of("nope", "key"), List.of("mS", "nope"), List.of("mH", "mH", "key"));

    FactViewTest() {
        f.kb.add(Frame.classFrame("Target").slot(Slot.builder("key", DataType.INTEGER).defaultValue(Value.of(7))
                .build()).build());
        f.kb.add(Frame.classFrame("Holder").slot(Slot.builder("mS", DataType.FRAME).build())
                .slot(Slot.builder("mH", DataType.FRAME).build()).build());
        f.assertFact("t1", "Target", "key", 1);
        f.assertFact("t2", "Target");
        f.assertFact("h1", "Holder", "mS", "@t1");
        f.assertFact("h2", "Holder", "mH", "@h1");
        f.assertFact("h3", "Holder", "mS", "@t2", "mH", "@h2");
        f.kb.frames().stream().filter(Frame::isInstance).forEach(facts::put);
    }

    /** Every path from every fact reads what following it by name reads, twice (the second time from the links). */
    private void assertFollowReadsAsByName(String... names) {
        for (int round = 0; round < 2; round++) {
            for (String n : names) {
                for (List<String> path : PATHS) {
                    assertThat(facts.follow(facts.touch(n), path, conditions)).as("%s.%s", n, path)
                            .isEqualTo(conditions.follow(Value.ref(n), path));
                }
            }
        }
    }

    @Test
    void follow_readsWhatFollowingByNameReads_ownInheritedAndMissingValuesAlike() {
        assertFollowReadsAsByName("t1", "t2", "h1", "h2", "h3");
        assertThat(facts.follow(facts.get("h2"), List.of("mH", "mS", "key"), conditions)).contains(Value.of(1));
        assertThat(facts.follow(facts.get("h3"), List.of("mS", "key"), conditions)).contains(Value.of(7));
    }

    @Test
    void follow_whenAReferredFactLeftAndCameBack_readsTheNewFactNotTheOneItResolvedBefore() {
        assertFollowReadsAsByName("h1", "h2");
        facts.remove("t1");
        // Not in the view: read from the knowledge base, as by name.
        assertFollowReadsAsByName("h1", "h2");
        facts.put(Frame.instance("t1", "Target").provenance(Provenance.RUNTIME)
                .slot(Fixture.num("key", 42)).build());
        assertFollowReadsAsByName("h1", "h2");
        assertThat(facts.follow(facts.get("h2"), List.of("mH", "mS", "key"), conditions)).contains(Value.of(42));
    }

    @Test
    void follow_whenTheFactsFrameChanged_resolvesItsNewReferences() {
        assertFollowReadsAsByName("h1", "h2");
        facts.put(Frame.instance("h1", "Holder").provenance(Provenance.RUNTIME)
                .slot(Slot.builder("mS", DataType.FRAME).value(Value.ref("t2")).build()).build());
        assertFollowReadsAsByName("h1", "h2");
        assertThat(facts.follow(facts.get("h2"), List.of("mH", "mS", "key"), conditions)).contains(Value.of(7));
    }

    @Test
    void follow_throughAReferenceToAnUnknownInstance_readsNothing() {
        facts.put(Frame.instance("h9", "Holder").provenance(Provenance.RUNTIME)
                .slot(Slot.builder("mS", DataType.FRAME).value(Value.ref("ghost")).build()).build());
        assertFollowReadsAsByName("h9");
        assertThat(facts.follow(facts.get("h9"), List.of("mS", "key"), conditions)).isEmpty();
    }

    @Test
    void follow_alongAPathLongerThanIsRead_stopsWhereFollowingByNameStops() {
        facts.put(Frame.instance("loop", "Holder").provenance(Provenance.RUNTIME)
                .slot(Slot.builder("mH", DataType.FRAME).value(Value.ref("loop")).build()).build());
        List<String> path = new ArrayList<>(Collections.nCopies(Conditions.MAX_PATH + 3, "mH"));
        path.add("key");
        Optional<Value> byName = conditions.follow(Value.ref("loop"), path);
        assertThat(facts.follow(facts.get("loop"), path, conditions)).isEqualTo(byName).contains(Value.ref("loop"));
        List<String> exact = new ArrayList<>(Collections.nCopies(Conditions.MAX_PATH, "mH"));
        assertThat(facts.follow(facts.get("loop"), exact, conditions))
                .isEqualTo(conditions.follow(Value.ref("loop"), exact)).contains(Value.ref("loop"));
    }

    @Test
    void memberships_oneHeldAsItself_moreAsAnArray_areFoundLeftAndTakenOutOfTheirMemories() {
        List<SlotPattern> patterns = new ArrayList<>();
        for (String slot : List.of("mA", "mB", "mC")) {
            patterns.add(new SlotPattern(patterns.size(), slot, "Target", org.kicnp.core.Condition.ANY, "COND_ANY",
                    true, true, false, false, java.util.Set.of(), Optional.empty()));
        }
        Rule r = Rule.of("R", 0, 1, 0, patterns, List.of(), Optional.empty());
        List<AlphaMemory> memories = patterns.stream().map(p -> new AlphaMemory(r, p)).toList();
        FactView.Fact t = facts.touch("t1");
        List<AlphaMemory.Entry> entries = new ArrayList<>();
        for (AlphaMemory m : memories) {
            assertThat(t.entryIn(m)).isNull();
            AlphaMemory.Entry e = m.add(t, (fact, path) -> null);
            t.enter(e);
            entries.add(e);
            for (int i = 0; i < entries.size(); i++) {
                assertThat(t.entryIn(memories.get(i))).isSameAs(entries.get(i));
            }
        }

        t.leave(memories.get(0)); // three to two, then to one: each left memory is no longer found, the others are
        assertThat(t.entryIn(memories.get(0))).isNull();
        assertThat(t.entryIn(memories.get(1))).isSameAs(entries.get(1));
        t.leave(memories.get(1));
        assertThat(t.entryIn(memories.get(1))).isNull();
        assertThat(t.entryIn(memories.get(2))).isSameAs(entries.get(2));
        t.enter(entries.get(1)); // one to two again
        assertThat(t.entryIn(memories.get(1))).isSameAs(entries.get(1));

        t.leaveAll(); // takes it out of the memories it is in; the one it left stays as its caller leaves it
        assertThat(memories).extracting(AlphaMemory::size).containsExactly(1, 0, 0);
        assertThat(memories).allSatisfy(m -> assertThat(t.entryIn(m)).isNull());
        t.enter(entries.get(0)); // and from none to one
        assertThat(t.entryIn(memories.get(0))).isSameAs(entries.get(0));
    }

    /**
     * A firing gives its new instance's record the links of the frame it just added before the engine has seen that
     * frame: they are kept when the frame arrives, and let go only when another frame replaces it.
     */
    @Test
    void linksGivenBeforeTheFrameIsSeen_areKeptForIt_andLetGoWhenAnotherFrameReplacesIt() {
        Frame h1 = f.kb.frame("h1").orElseThrow();
        FactView.Fact fresh = new FactView.Fact("h9");
        FactView.Fact[] given = {facts.get("t1"), null};
        fresh.links = given;

        fresh.seen(h1);
        assertThat(fresh.links).isSameAs(given);
        fresh.seen(h1); // the same frame again
        assertThat(fresh.links).isSameAs(given);
        fresh.seen(h1.withSlot(Slot.ofValue("mS", DataType.FRAME, Value.ref("t2"))));
        assertThat(fresh.links).isNull();
        assertThat(fresh.gone()).isFalse();
    }
}
