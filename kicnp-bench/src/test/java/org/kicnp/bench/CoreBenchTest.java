package org.kicnp.bench;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;

class CoreBenchTest {

    @Test
    void core_onSmallKnowledgeBase_endsWithJsonOfPositiveFigures() throws Exception {
        Output run = run("core", "--frames", "2000", "--warmup", "1", "--rounds", "3", "--adds", "3000");

        assertThat(run.code()).as(run.err()).isZero();
        List<String> lines = run.out().lines().toList();
        JsonNode json = new ObjectMapper().readTree(lines.get(lines.size() - 1));
        assertThat(json.get("frames").asInt()).isEqualTo(2000);
        for (String key : List.of("load_s", "save_s", "heap_mb", "query_us_per_result", "add_us_per_instance")) {
            assertThat(json.has(key)).as(key).isTrue();
            assertThat(json.get(key).isNumber()).as(key).isTrue();
            assertThat(json.get(key).asDouble()).as(key).isPositive();
        }
        assertThat(run.out()).contains("load (XML -> knowledge base)", "add instance, one apply each")
                .containsPattern("(PASS|MISS)");
    }

    @Test
    void core_whenFramesTooFew_isAUsageError() throws Exception {
        Output run = run("core", "--frames", "1");

        assertThat(run.code()).isEqualTo(2);
        assertThat(run.err()).contains("--frames");
    }

    @Test
    void help_listsTheCoreBench() throws Exception {
        Output run = run("--help");

        assertThat(run.code()).isZero();
        assertThat(run.out()).contains("core");
    }

    private record Output(int code, String out, String err) {
    }

    private static synchronized Output run(String... args) {
        PrintStream oldOut = System.out;
        PrintStream oldErr = System.err;
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        try {
            System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
            int code = BenchMain.run(args);
            return new Output(code, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
        } finally {
            System.setOut(oldOut);
            System.setErr(oldErr);
        }
    }
}
