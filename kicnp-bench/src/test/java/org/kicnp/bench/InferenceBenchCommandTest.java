package org.kicnp.bench;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.kicnp.core.Frame;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

class InferenceBenchCommandTest {

    @Test
    void expectedFirings_countsEveryLevelPerKeyGroup_includingAPartialLastGroup() {
        assertThat(new InferenceWorkload(4).expectedFirings()).isEqualTo(2 + 2 + 4);
        assertThat(new InferenceWorkload(8).expectedFirings()).isEqualTo(16);
        // s0, s1 = StimA, s2 = StimB of key 0: two Pairs and nothing deeper without a StimC
        assertThat(new InferenceWorkload(3).expectedFirings()).isEqualTo(2);
        assertThat(new InferenceWorkload(2).expectedFirings()).isZero();
    }

    @Test
    void bothEngines_onTheSameWorkload_fireExactlyTheExpectedNumberOfTimes() {
        InferenceWorkload w = new InferenceWorkload(203);
        EngineResult kicnp = KicnpInferenceRun.run(w);
        EngineResult drools = DroolsInferenceRun.compile().run(w);

        assertThat(kicnp.firings()).isEqualTo(w.expectedFirings()).isEqualTo(drools.firings()).isEqualTo(50 * 8 + 2);
        assertThat(InferenceBenchCommand.check(w, kicnp, drools)).isEqualTo(402);
    }

    @Test
    void storeOnly_addsTheInstancesTheEngineDerived_inItsOrder_toAKnowledgeBaseWithoutAnEngine() {
        InferenceWorkload w = new InferenceWorkload(203);

        KicnpInferenceRun.Stored stored = KicnpInferenceRun.stored(w);
        List<Frame> derived = stored.derived();
        EngineResult store = KicnpInferenceRun.storeOnly(w, stored);

        assertThat(derived).hasSize((int) w.expectedFirings());
        assertThat(derived).extracting(f -> f.parent().orElseThrow()).containsOnly("Pair", "Triple", "Alert");
        // in commit order: every instance a derived one refers to (a stimulus or an earlier derived one) came before
        Set<String> seen = new HashSet<>();
        for (int i = 0; i < w.n(); i++) {
            seen.add("s" + i);
        }
        int refs = 0;
        for (Frame f : derived) {
            for (Slot s : f.slots()) {
                if (s.effectiveValue().orElse(null) instanceof Value.Ref(String target)) {
                    assertThat(seen).as("%s refers to %s", f.name(), target).contains(target);
                    refs++;
                }
            }
            seen.add(f.name());
        }
        assertThat(refs).isEqualTo(2 * derived.size());
        assertThat(stored.stimuli()).hasSize(w.n());
        assertThat(store.firings()).isEqualTo(derived.size());
        assertThat(store.seconds()).isPositive();
    }

    @Test
    void droolsWithInsertLogical_firesAsOften_andItsDrlUsesTruthMaintenance() {
        InferenceWorkload w = new InferenceWorkload(203);

        EngineResult logical = DroolsInferenceRun.compile(true).run(w);

        assertThat(logical.firings()).isEqualTo(w.expectedFirings());
        assertThat(InferenceWorkload.drl(true)).contains("insertLogical( new Pair").doesNotContain("  insert(");
        assertThat(InferenceWorkload.drl(false)).contains("insert( new Alert").doesNotContain("insertLogical");
    }

    @Test
    void check_whenTheEnginesFireDifferently_failsNamingBothCounts() {
        InferenceWorkload w = new InferenceWorkload(8);

        assertThatThrownBy(() -> InferenceBenchCommand.check(w, new EngineResult(16, 1, 1), new EngineResult(15, 1, 1)))
                .isInstanceOf(InferenceBenchCommand.FiringsDifferException.class)
                .hasMessageContaining("K-ICNP fired 16 times, Drools 15 times, the workload expects 16");
    }

    @Test
    void inference_tinyConfiguration_printsTheTableThenOneJsonObjectWithEveryFigure() throws Exception {
        StringWriter out = inference("--runs", "1", "--latency-samples", "200", "--latency-warmup", "200");

        List<String> lines = out.toString().lines().toList();
        assertThat(out.toString()).contains("same explicit priorities").contains("firings")
                .contains("Graal compiler");
        JsonNode json = new ObjectMapper().readTree(lines.get(lines.size() - 1));
        assertThat(json.fieldNames()).toIterable()
                .containsExactly("runs", "script_us_median", "stimulus_to_action_us_p99");
        JsonNode run = json.get("runs").get(0);
        assertThat(run.fieldNames()).toIterable().containsExactly("n", "firings", "kicnp_s", "drools_s", "ratio",
                "drools_logical_s", "ratio_logical", "kicnp_kb_only_s", "ratio_paired_median", "ratio_paired_min",
                "ratio_paired_max", "kicnp_retained_mb", "drools_retained_mb");
        assertThat(run.get("n").asInt()).isEqualTo(200);
        assertThat(run.get("firings").asLong()).isEqualTo(new InferenceWorkload(200).expectedFirings()).isEqualTo(400);
        assertThat(run.get("kicnp_s").asDouble()).isPositive();
        assertThat(run.get("drools_s").asDouble()).isPositive();
        assertThat(run.get("ratio").asDouble())
                .isCloseTo(run.get("kicnp_s").asDouble() / run.get("drools_s").asDouble(), org.assertj.core.data.Percentage.withPercentage(1));
        assertThat(run.get("ratio_logical").asDouble()).isCloseTo(
                run.get("kicnp_s").asDouble() / run.get("drools_logical_s").asDouble(),
                org.assertj.core.data.Percentage.withPercentage(1));
        assertThat(run.get("kicnp_kb_only_s").asDouble()).isPositive();
        // one run: its one pair is the median, the least and the greatest
        assertThat(run.get("ratio_paired_median").asDouble()).isCloseTo(run.get("ratio").asDouble(),
                org.assertj.core.data.Percentage.withPercentage(1));
        assertThat(run.get("ratio_paired_min").asDouble()).isEqualTo(run.get("ratio_paired_median").asDouble());
        assertThat(run.get("ratio_paired_max").asDouble()).isEqualTo(run.get("ratio_paired_median").asDouble());
        assertThat(out.toString()).contains("KB only s").contains("KB/Drools").contains("paired (min-max)");
        // 200 stimuli and 400 firings keep a few hundred kilobytes in either engine, within the heap reading's
        // settling margin (a quarter of a megabyte), so only the scale is checked here
        assertThat(run.get("kicnp_retained_mb").isNumber()).isTrue();
        assertThat(run.get("kicnp_retained_mb").asDouble()).isBetween(-1.0, 10.0);
        assertThat(run.get("drools_retained_mb").asDouble()).isBetween(-1.0, 10.0);
        assertThat(out.toString()).contains("heap kept by one run");
        assertThat(json.get("script_us_median").asDouble()).isPositive();
        assertThat(json.get("stimulus_to_action_us_p99").asDouble()).isPositive();
        assertThat(out.toString()).doesNotContain(" run 1: ");
    }

    @Test
    void inference_printRuns_givesEachTimedRunsTimes_whoseMediansAreTheJsonsFigures() throws Exception {
        StringWriter out = inference("--runs", "3", "--latency-samples", "100", "--latency-warmup", "100",
                "--print-runs");

        List<String> lines = out.toString().lines().toList();
        java.util.regex.Pattern runLine = java.util.regex.Pattern.compile(
                "  N=200 run (\\d): K-ICNP ([0-9.]+) s, Drools ([0-9.]+) s, pair ([0-9.]+), Drools TMS ([0-9.]+) s, "
                        + "KB only ([0-9.]+) s");
        List<double[]> runs = new java.util.ArrayList<>();
        for (String line : lines) {
            java.util.regex.Matcher m = runLine.matcher(line);
            if (m.matches()) {
                assertThat(Integer.parseInt(m.group(1))).isEqualTo(runs.size() + 1);
                runs.add(new double[] {Double.parseDouble(m.group(2)), Double.parseDouble(m.group(3)),
                        Double.parseDouble(m.group(4))});
            }
        }
        assertThat(runs).hasSize(3);
        JsonNode run = new ObjectMapper().readTree(lines.get(lines.size() - 1)).get("runs").get(0);
        double[] kicnp = runs.stream().mapToDouble(r -> r[0]).sorted().toArray();
        double[] pairs = runs.stream().mapToDouble(r -> r[2]).sorted().toArray();
        // printed to 6 decimals (seconds) and 3 (pairs): the medians agree to that
        assertThat(kicnp[1]).isCloseTo(run.get("kicnp_s").asDouble(), org.assertj.core.data.Offset.offset(0.000002));
        assertThat(pairs[1]).isCloseTo(run.get("ratio_paired_median").asDouble(),
                org.assertj.core.data.Offset.offset(0.0006));
        for (double[] r : runs) {
            assertThat(r[0]).isPositive();
            assertThat(r[1]).isPositive();
        }
    }

    /** The goal needs both estimates at or under 1: the ratio of the medians and the median of the paired ratios. */
    @Test
    void table_marksTheGoalMetOnlyWhenBothTheRatioAndThePairedRatioAreAtMostOne() {
        var f = new ActionLatencyProbe.Figures(100, 5, 6, 7, 8, 9, 10, 11, true, "GraalVM");
        String both = InferenceBenchCommand.table(List.of(run(10_000, 0.9, 1.0, 0.95)), 3, f);
        String medianOnly = InferenceBenchCommand.table(List.of(run(10_000, 0.9, 1.0, 1.08)), 3, f);
        String pairedOnly = InferenceBenchCommand.table(List.of(run(100_000, 1.1, 1.0, 0.97)), 3, f);

        assertThat(goalColumn(both)).isEqualTo("PASS");
        assertThat(goalColumn(medianOnly)).isEqualTo("MISS");
        assertThat(goalColumn(pairedOnly)).isEqualTo("MISS");
        assertThat(medianOnly).contains("1.08 (0.90-1.30)");
    }

    private static InferenceBenchCommand.InferenceRun run(int n, double kicnp, double drools, double paired) {
        return new InferenceBenchCommand.InferenceRun(n, 8, kicnp, drools, kicnp, drools, drools, 0.1, paired, 0.9, 1.3,
                1_000_000, 1_000_000);
    }

    /** The goal column of the table's one row. */
    private static String goalColumn(String table) {
        String row = table.lines().filter(l -> l.trim().startsWith("10,000") || l.trim().startsWith("100,000"))
                .findFirst().orElseThrow();
        return row.contains("PASS") ? "PASS" : row.contains("MISS") ? "MISS" : "?";
    }

    /** Runs {@code bench inference} at N = 200 after one warm-up run of 100, with {@code more} options; exits 0. */
    private static StringWriter inference(String... more) {
        StringWriter out = new StringWriter();
        CommandLine cli = new CommandLine(new BenchMain());
        cli.setOut(new PrintWriter(out));
        List<String> args = new java.util.ArrayList<>(
                List.of("inference", "--n", "200", "--warmup-n", "100", "--warmup-runs", "1"));
        args.addAll(List.of(more));
        assertThat(cli.execute(args.toArray(String[]::new))).isZero();
        return out;
    }
}
