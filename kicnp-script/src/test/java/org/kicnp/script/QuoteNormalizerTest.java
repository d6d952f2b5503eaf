package org.kicnp.script;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

class QuoteNormalizerTest {

    @Test
    void normalize_whenTypographicDelimiters_turnsThemIntoAsciiQuotes() {
        assertThat(QuoteNormalizer.normalize("f(“Hi!”, ‘x’)")).isEqualTo("f(\"Hi!\", 'x')");
    }

    @Test
    void normalize_whenTypographicQuotesInsideAsciiLiteralsOrComments_leavesThemAlone() {
        String source = "f(\"say “hi”\", 'don’t', `‘t’`) // “c”\n/* ‘d’ */ g(“don’t”)";

        assertThat(QuoteNormalizer.normalize(source))
                .isEqualTo("f(\"say “hi”\", 'don’t', `‘t’`) // “c”\n/* ‘d’ */ g(\"don’t\")");
    }

    @Test
    void normalize_whenAsciiQuoteInsideTypographicLiteral_escapesIt() {
        assertThat(QuoteNormalizer.normalize("f(“a \"b\" c”)")).isEqualTo("f(\"a \\\"b\\\" c\")");
    }

    @Test
    void normalize_whenUnterminated_leavesItForTheParser() {
        assertThat(QuoteNormalizer.normalize("f(“abc)\ng()")).isEqualTo("f(“abc)\ng()");
    }

    @Test
    void run_whenScriptCopiedFromThePaper_sendsTheMessage() {
        List<List<Object>> sent = Collections.synchronizedList(new ArrayList<>());
        try (ScriptRuntime runtime = ScriptRuntime.create(ScriptConfig.defaults().withTimeLimit(Duration.ofSeconds(10)))) {
            CompiledScript script = runtime.compile(new ScriptId("Greeting", "onInstantiate"),
                    "Sendmsg(s.mMouth, “Hi! Nice to meet you. Welcome to visit my room!”);");

            runtime.run(script, Map.of(
                    "s", Proxies.object(Map.of("mMouth", "mouth1", "mUser", "user1")),
                    "Sendmsg", Proxies.procedure(sent::add)));
        }

        assertThat(sent).containsExactly(List.of("mouth1", "Hi! Nice to meet you. Welcome to visit my room!"));
    }
}
