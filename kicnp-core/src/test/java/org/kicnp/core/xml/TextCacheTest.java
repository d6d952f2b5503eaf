package org.kicnp.core.xml;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class TextCacheTest {
    private final TextCache cache = new TextCache();

    @Test
    void text_whenSeenBefore_answersTheSameString() {
        String first = cache.text("xxTYPE_STRyy".toCharArray(), 2, 8);
        String again = cache.text("TYPE_STR".toCharArray(), 0, 8);

        assertThat(first).isEqualTo("TYPE_STR");
        assertThat(again).isSameAs(first);
    }

    @Test
    void text_whenManyTextsShareTheTable_alwaysAnswersTheExactText() {
        for (int i = 0; i < 20_000; i++) {
            String s = "C" + i;
            assertThat(cache.text(s.toCharArray(), 0, s.length())).isEqualTo(s);
            assertThat(cache.text("TRUE".toCharArray(), 0, 4)).isEqualTo("TRUE");
        }
    }

    @Test
    void text_whenLongerThanTheCacheKeeps_isStillExact() {
        String s = "a value much longer than thirty-two characters, written once";

        assertThat(cache.text(s.toCharArray(), 0, s.length())).isEqualTo(s);
    }
}
