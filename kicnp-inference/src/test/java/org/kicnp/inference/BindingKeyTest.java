package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.Arrays;
import org.junit.jupiter.api.Test;

/**
 * A binding's key keeps its first two instances in fields and the rest in an array: every width reads back the
 * instances it was given, in order, and keys are equal exactly when frame and instances are.
 */
class BindingKeyTest {

    @Test
    void everyWidth_readsBackItsInstancesInOrder_fromACopyOfTheArrayGiven() {
        for (int width = 0; width <= 4; width++) {
            String[] facts = new String[width];
            for (int i = 0; i < width; i++) {
                facts[i] = "f" + i;
            }
            BindingKey key = new BindingKey("R", facts);
            String[] given = facts.clone();
            Arrays.fill(facts, "changed"); // the caller's array is its own
            assertThat(key.width()).isEqualTo(width);
            assertThat(key.facts()).containsExactly(given);
            for (int i = 0; i < width; i++) {
                assertThat(key.fact(i)).isEqualTo("f" + i);
            }
            assertThat(key.toString()).isEqualTo("R" + Arrays.toString(given));
            // the hash is the one the key had when it held an array
            assertThat(key.hashCode()).isEqualTo(31 * "R".hashCode() + Arrays.hashCode(given));
        }
    }

    @Test
    void keysAreEqualExactlyWhenFrameAndInstancesAre() {
        BindingKey ab = new BindingKey("R", new String[] {"a", "b"});
        assertThat(ab).isEqualTo(new BindingKey("R", new String[] {"a", "b"}))
                .hasSameHashCodeAs(new BindingKey("R", new String[] {"a", "b"}));
        assertThat(ab).isNotEqualTo(new BindingKey("S", new String[] {"a", "b"}))
                .isNotEqualTo(new BindingKey("R", new String[] {"b", "a"}))
                .isNotEqualTo(new BindingKey("R", new String[] {"a"}))
                .isNotEqualTo(new BindingKey("R", new String[] {"a", "b", "c"}));
        assertThat(new BindingKey("R", new String[] {"a", "b", "c"}))
                .isEqualTo(new BindingKey("R", new String[] {"a", "b", "c"}))
                .isNotEqualTo(new BindingKey("R", new String[] {"a", "b", "d"}));
        assertThat(new BindingKey("R", new String[0])).isEqualTo(new BindingKey("R", new String[0]))
                .isNotEqualTo(ab);
    }

    @Test
    void anInstancePastTheWidth_isNotThere() {
        BindingKey one = new BindingKey("R", new String[] {"a"});
        assertThatThrownBy(() -> one.fact(1)).isInstanceOf(NullPointerException.class);
        BindingKey three = new BindingKey("R", new String[] {"a", "b", "c"});
        assertThatThrownBy(() -> three.fact(3)).isInstanceOf(ArrayIndexOutOfBoundsException.class);
    }
}
