package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.kicnp.core.Condition;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Value;

/**
 * An alpha memory files each member under the key each indexed path reaches from it, and a membership remembers those
 * keys (one field: the first index's key alone, or an array once another index has one) so that a re-key or a removal
 * unfiles the member from exactly the buckets it is in.
 */
class AlphaMemoryTest {

    private final FactView facts = new FactView(KnowledgeBase.create());
    /** What each fact reaches along each path, as the test sets it: fact name → path's first step → key. */
    private final Map<String, Map<String, Value>> reach = new HashMap<>();

    private AlphaMemory memory(String... paths) {
        SlotPattern p = new SlotPattern(0, "mA", "Target", Condition.ANY, "COND_ANY", true, true, false, false, Set.of(),
                Optional.empty());
        AlphaMemory m = new AlphaMemory(Rule.of("R", 0, 1, 0, List.of(p), List.of(), Optional.empty()), p);
        for (int i = 0; i < paths.length; i++) {
            assertThat(m.addIndex(List.of(paths[i]))).isEqualTo(i);
        }
        return m;
    }

    private void reaches(String fact, String path, Integer key) {
        reach.computeIfAbsent(fact, k -> new HashMap<>()).put(path, key == null ? null : Value.of(key));
    }

    private AlphaMemory.Entry add(AlphaMemory m, String fact) {
        return m.add(facts.touch(fact), (f, path) -> reach.getOrDefault(f.name, Map.of()).get(path.getFirst()));
    }

    private void rekey(AlphaMemory m, AlphaMemory.Entry e) {
        m.rekey(e, (f, path) -> reach.getOrDefault(f.name, Map.of()).get(path.getFirst()));
    }

    private List<String> bucket(AlphaMemory m, int index, int key) {
        return Bag.<FactView.Fact>toList(m.bucket(index, Value.of(key))).stream().map(f -> f.name).toList();
    }

    @Test
    void oneIndex_membersAreFiledUnderTheirKey_rekeyedAndUnfiledWhenRemoved() {
        AlphaMemory m = memory("key");
        reaches("a", "key", 1);
        reaches("b", "key", 1);
        reaches("c", "key", null); // its path reaches nothing: in the memory, under no key
        AlphaMemory.Entry a = add(m, "a");
        AlphaMemory.Entry b = add(m, "b");
        AlphaMemory.Entry c = add(m, "c");
        assertThat(bucket(m, 0, 1)).containsExactly("a", "b");
        assertThat(a.key(0)).isEqualTo(Value.of(1));
        assertThat(c.key(0)).isNull();

        reaches("a", "key", 2);
        rekey(m, a);
        reaches("c", "key", 2);
        rekey(m, c);
        assertThat(bucket(m, 0, 1)).containsExactly("b");
        assertThat(bucket(m, 0, 2)).containsExactly("a", "c");

        m.remove(a);
        m.remove(b);
        assertThat(bucket(m, 0, 1)).isEmpty();
        assertThat(bucket(m, 0, 2)).containsExactly("c");
        assertThat(m.size()).isEqualTo(1);
    }

    @Test
    void twoIndexes_eachMemberIsFiledUnderBoth_whicheverHasAKey_andLeavesExactlyThoseBuckets() {
        AlphaMemory m = memory("key", "room");
        reaches("a", "key", 1);
        reaches("a", "room", 10);
        reaches("b", "key", 1); // no room yet: only the first index has a key
        reaches("c", "room", 10); // no key: only the second has one
        AlphaMemory.Entry a = add(m, "a");
        AlphaMemory.Entry b = add(m, "b");
        AlphaMemory.Entry c = add(m, "c");
        assertThat(bucket(m, 0, 1)).containsExactly("a", "b");
        assertThat(bucket(m, 1, 10)).containsExactly("a", "c");
        assertThat(List.of(a.key(0), a.key(1))).containsExactly(Value.of(1), Value.of(10));
        assertThat(b.key(1)).isNull();
        assertThat(c.key(0)).isNull();

        reaches("b", "room", 11); // b gains a second key, keeping its first
        rekey(m, b);
        reaches("c", "key", 3); // c gains a first key, keeping its second
        rekey(m, c);
        reaches("a", "key", null); // a loses its first key, keeping its second
        rekey(m, a);
        assertThat(List.of(b.key(0), b.key(1))).containsExactly(Value.of(1), Value.of(11));
        assertThat(List.of(c.key(0), c.key(1))).containsExactly(Value.of(3), Value.of(10));
        assertThat(a.key(0)).isNull();
        assertThat(a.key(1)).isEqualTo(Value.of(10));
        assertThat(bucket(m, 0, 1)).containsExactly("b");
        assertThat(bucket(m, 0, 3)).containsExactly("c");
        assertThat(bucket(m, 1, 10)).containsExactly("a", "c");
        assertThat(bucket(m, 1, 11)).containsExactly("b");

        m.remove(c);
        m.remove(b);
        assertThat(bucket(m, 0, 1)).isEmpty();
        assertThat(bucket(m, 0, 3)).isEmpty();
        assertThat(bucket(m, 1, 11)).isEmpty();
        assertThat(bucket(m, 1, 10)).containsExactly("a");
        m.remove(a);
        assertThat(bucket(m, 1, 10)).isEmpty();
        assertThat(m.size()).isZero();
    }
}
