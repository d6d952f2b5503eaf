package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

class BindingTest {

    @Test
    void wrap_readsLikeAnOrderedMapOfTheSlotsToTheirInstances() {
        Binding b = Binding.wrap(List.of("mA", "mB", "mC"), new String[] {"s1", "s2", "s3"});

        assertThat(b.get("mB")).isEqualTo("s2");
        assertThat(b.get("mX")).isNull();
        assertThat(b.containsKey("mC")).isTrue();
        assertThat(b.containsValue("s1")).isTrue();
        assertThat(b.containsValue("s9")).isFalse();
        assertThat(b).hasSize(3);
        assertThat(b.keySet()).containsExactly("mA", "mB", "mC");
        assertThat(b.values()).containsExactly("s1", "s2", "s3");
        List<String> seen = new ArrayList<>();
        b.forEach((slot, fact) -> seen.add(slot + "=" + fact));
        assertThat(seen).containsExactly("mA=s1", "mB=s2", "mC=s3");
    }

    @Test
    void binding_equalsAndHashesLikeAnyMapWithTheSameEntries() {
        Binding b = Binding.wrap(List.of("mA", "mB"), new String[] {"s1", "s2"});

        assertThat(b).isEqualTo(Map.of("mB", "s2", "mA", "s1"));
        assertThat(b.hashCode()).isEqualTo(Map.of("mA", "s1", "mB", "s2").hashCode());
        assertThat(b).isNotEqualTo(Map.of("mA", "s1", "mB", "s3"));
    }

    @Test
    void binding_refusesChanges() {
        Binding b = Binding.wrap(List.of("mA"), new String[] {"s1"});

        assertThatThrownBy(() -> b.put("mB", "s2")).isInstanceOf(UnsupportedOperationException.class);
        assertThatThrownBy(() -> b.remove("mA")).isInstanceOf(UnsupportedOperationException.class);
        assertThatThrownBy(() -> b.values().clear()).isInstanceOf(UnsupportedOperationException.class);
        assertThatThrownBy(() -> b.entrySet().iterator().next().setValue("s9"))
                .isInstanceOf(UnsupportedOperationException.class);
        assertThat(b).containsExactly(Map.entry("mA", "s1"));
    }

    @Test
    void copyOf_keepsTheGivenOrderAndIsNotChangedByTheOriginal() {
        Map<String, String> m = new LinkedHashMap<>();
        m.put("mZ", "s1");
        m.put("mA", "s2");
        Binding b = Binding.copyOf(m);
        m.put("mZ", "changed");

        assertThat(b.keySet()).containsExactly("mZ", "mA");
        assertThat(b.get("mZ")).isEqualTo("s1");
        assertThat(Binding.copyOf(b)).isSameAs(b);
        assertThat(Binding.copyOf(Map.of())).isEmpty();
    }

    @Test
    void wrap_withMoreSlotsThanInstances_isRefusedNamingBothCounts() {
        assertThatThrownBy(() -> Binding.wrap(List.of("mA", "mB"), new String[] {"s1"}))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("2 slots, 1 instances");
    }
}
