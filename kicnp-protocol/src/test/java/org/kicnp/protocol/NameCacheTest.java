package org.kicnp.protocol;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;

import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

class NameCacheTest {

    private static String of(String text) {
        byte[] b = ("xx" + text + "yy").getBytes(UTF_8);
        return NameCache.of(b, 2, b.length - 2);
    }

    @Test
    void of_theSameAsciiNameTwice_answersTheSameStringObject() {
        String first = of("robot-scout");

        assertThat(of("robot-scout")).isEqualTo("robot-scout").isSameAs(first);
    }

    @Test
    void of_manyNamesSharingSlots_answersEachItsOwnText() {
        Set<String> seen = new HashSet<>();
        for (int round = 0; round < 2; round++) {
            for (int i = 0; i < 20_000; i++) {
                String name = "agent-" + i;
                assertThat(of(name)).isEqualTo(name);
                seen.add(name);
            }
        }
        assertThat(seen).hasSize(20_000);
    }

    @Test
    void of_emptyNonAsciiAndLongNames_areDecodedAsUtf8() {
        assertThat(of("")).isEmpty();
        assertThat(of("ロボビー")).isEqualTo("ロボビー");
        String longName = "n".repeat(100);
        assertThat(of(longName)).isEqualTo(longName);
    }
}
