package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import org.kicnp.core.Change;
import org.kicnp.core.ConditionParser;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;

/**
 * A change set of many new instances is prepared in one go (the engine makes their fact records before it matches
 * any of them, {@code ForwardChainer.prepare}); what the engine derives must not depend on that.
 */
class LargeBatchTest {

    @Test
    void aLargeBatchOfAddsRemovesAndReplaces_derivesWhatTheSameChangesOneByOneDerive() {
        Fixture batched = fixture();
        InferenceEngine batchedEngine = started(batched);
        Fixture single = fixture();
        InferenceEngine singleEngine = started(single);
        List<Change> changes = changes();
        assertThat(changes).hasSizeGreaterThanOrEqualTo(64); // the size from which a change set is prepared

        batched.kb.apply(changes);
        batchedEngine.runToQuiescence();
        for (Change c : changes) {
            single.kb.apply(List.of(c));
        }
        singleEngine.runToQuiescence();

        Set<String> pairs = bindings(batched);
        assertThat(pairs).isEqualTo(bindings(single));
        // The batch's new instances met each other and the old ones (b10 has key 0, b29 key 19); a5 took key 6, so its
        // pair with b5 went and it met b6 (from before the batch) and b16; b109 (key 99) found no partner.
        assertThat(pairs).contains("a0+b0", "a0+b10", "a3+b13", "a19+b29", "a5+b6", "a5+b16")
                .doesNotContain("a5+b5");
        assertThat(pairs).noneMatch(p -> p.endsWith("+b109"));
    }

    /** Classes A and B with a key and the Pair frame joining them on it. */
    private static Fixture fixture() {
        Fixture f = new Fixture();
        f.cls("Thing", null);
        f.kb.add(Frame.classFrame("A").parent("Thing").slot(Fixture.num("key", 0)).build());
        f.kb.add(Frame.classFrame("B").parent("Thing").slot(Fixture.num("key", 0)).build());
        f.kb.add(Frame.classFrame("Pair") // shared, not unique: a fact may be in any number of pairs
                .slot(Slot.builder("mA", DataType.INSTANCE).argument("A").required(true).build())
                .slot(Slot.builder("mB", DataType.INSTANCE).argument("B").required(true)
                        .condition(ConditionParser.parse(".key == mA.key")).build()).build());
        return f;
    }

    /** Its engine, after 10 of each class (keys 0-9) and z0-z4 (A, keys 1000+) were added one by one and matched. */
    private static InferenceEngine started(Fixture f) {
        InferenceEngine e = f.engine();
        for (int i = 0; i < 10; i++) {
            f.assertFact("a" + i, "A", "key", (long) i);
            f.assertFact("b" + i, "B", "key", (long) i);
        }
        for (int i = 0; i < 5; i++) {
            f.assertFact("z" + i, "A", "key", 1000L + i);
        }
        e.runToQuiescence();
        assertThat(f.instancesOf("Pair")).hasSize(10);
        return e;
    }

    /**
     * z0-z4 removed, a5-a9 given the next key, b10-b109 (keys 0-99) and a10-a19 (keys 10-19) added: enough Bs that
     * the memory of Pair's mB makes room for them before the batch goes in ({@code AlphaMemory.expect}; what that
     * keeps is checked in {@code MatchNetworkTest}).
     */
    private static List<Change> changes() {
        List<Change> out = new ArrayList<>();
        for (int i = 0; i < 5; i++) {
            out.add(new Change.Remove("z" + i));
        }
        for (int i = 5; i < 10; i++) {
            out.add(new Change.Replace(instance("a" + i, "A", i + 1)));
        }
        for (int i = 10; i < 110; i++) {
            out.add(new Change.Add(instance("b" + i, "B", i - 10)));
        }
        for (int i = 10; i < 20; i++) {
            out.add(new Change.Add(instance("a" + i, "A", i)));
        }
        return out;
    }

    private static Frame instance(String name, String cls, long key) {
        return Frame.instance(name, cls).provenance(Provenance.RUNTIME).slot(Fixture.num("key", key)).build();
    }

    /** Each live Pair as "mA+mB". */
    private static Set<String> bindings(Fixture f) {
        Set<String> out = new TreeSet<>();
        for (Frame p : f.kb.instancesOf("Pair")) {
            out.add(f.kb.value(p.name(), "mA").orElseThrow().text() + "+"
                    + f.kb.value(p.name(), "mB").orElseThrow().text());
        }
        return out;
    }
}
