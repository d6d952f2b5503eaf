package org.kicnp.bench;

import java.io.PrintWriter;
import java.lang.management.ManagementFactory;
import java.math.BigDecimal;
import java.math.MathContext;
import java.util.Locale;

/**
 * The figures of one {@link CoreBench} run, printed as a table with each figure beside its target, and as one
 * JSON object on the last line for scripts. A figure is printed as measured, whether or not it meets its target.
 */
final class CoreReport {
    static final double LOAD_TARGET_S = 1.5;
    static final double SAVE_TARGET_S = 1.0;
    static final double HEAP_TARGET_MB = 150;
    static final double QUERY_TARGET_US = 1.0;

    private final int frames;
    private final int classes;
    private final int instances;
    private final long xmlBytes;
    private final int warmup;
    private final int rounds;
    private final Timed load;
    private final Timed save;
    private final double heapMb;
    private final QueryTiming.Result query;
    private final AddTiming.Result added;

    CoreReport(int frames, int classes, int instances, long xmlBytes, int warmup, int rounds, Timed load,
            Timed save, double heapMb, QueryTiming.Result query, AddTiming.Result added) {
        this.frames = frames;
        this.classes = classes;
        this.instances = instances;
        this.xmlBytes = xmlBytes;
        this.warmup = warmup;
        this.rounds = rounds;
        this.load = load;
        this.save = save;
        this.heapMb = heapMb;
        this.query = query;
        this.added = added;
    }

    void print(PrintWriter out) {
        out.printf(Locale.ROOT, "K-ICNP core bench: %d frames (%d classes, %d instances), IS-A tree %d deep, "
                + "6 slots per frame, XML %.1f MB%n", frames, classes, instances, KnowledgeGenerator.DEPTH,
                xmlBytes / (1024.0 * 1024.0));
        out.printf(Locale.ROOT, "%d untimed warm-up rounds, then the median of %d timed rounds; Java %s, %d CPUs, "
                + "system load average %.1f%n%n", warmup, rounds, Runtime.version(),
                Runtime.getRuntime().availableProcessors(),
                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
        out.printf(Locale.ROOT, "%-30s %12s %14s  %-4s  %s%n", "measure", "figure", "target", "", "spread");
        row(out, "load (XML -> knowledge base)", load.wall().median(), "s", LOAD_TARGET_S, spread(load));
        row(out, "save (knowledge base -> XML)", save.wall().median(), "s", SAVE_TARGET_S, spread(save));
        row(out, "retained heap", heapMb, "MB", HEAP_TARGET_MB,
                String.format(Locale.ROOT, "%.0f bytes per frame", heapMb * 1024 * 1024 / frames));
        row(out, "instancesOf per result", query.usPerResult(), "us", QUERY_TARGET_US, Double.isNaN(query.cpuUsPerResult())
                ? "all depths together (below)"
                : "all depths together (below); thread CPU " + number(query.cpuUsPerResult()) + " us");
        out.printf(Locale.ROOT, "%-30s %12s %14s  %-4s  %s%n", "add instance, one apply each",
                number(added.usPerAdd()) + " us", "(no target)", "", String.format(Locale.ROOT,
                        "%,d adds, 2 instance slots each; thread CPU %s us, %,.0f bytes allocated per add",
                        added.adds(), number(added.cpuUsPerAdd()), added.bytesPerAdd()));
        out.println();
        out.printf(Locale.ROOT, "%-8s %8s %16s %14s%n", "depth", "classes", "results/query", "us/result");
        for (QueryTiming.Depth d : query.depths()) {
            out.printf(Locale.ROOT, "%-8d %8d %16.1f %14s%n", d.depth(), d.classes(), d.resultsPerQuery(),
                    number(d.usPerResult()));
        }
        out.println();
        out.println(json());
    }

    /** The one-line JSON summary, the last line of the output. */
    String json() {
        return String.format(Locale.ROOT,
                "{\"frames\": %d, \"load_s\": %s, \"save_s\": %s, \"heap_mb\": %s, \"query_us_per_result\": %s, "
                        + "\"add_us_per_instance\": %s}",
                frames, number(load.wall().median()), number(save.wall().median()), number(heapMb),
                number(query.usPerResult()), number(added.usPerAdd()));
    }

    private static String spread(Timed t) {
        String wall = String.format(Locale.ROOT, "min %.3f, max %.3f", t.wall().min(), t.wall().max());
        return t.cpu().size() == 0 ? wall : wall + String.format(Locale.ROOT, "; process CPU %.3f s", t.cpu().median());
    }

    private static void row(PrintWriter out, String measure, double figure, String unit, double target, String note) {
        out.printf(Locale.ROOT, "%-30s %12s %14s  %-4s  %s%n", measure, number(figure) + " " + unit,
                "<= " + number(target) + " " + unit, figure <= target ? "PASS" : "MISS", note);
    }

    /** Four significant digits, plain notation: readable, and a valid JSON number. */
    private static String number(double value) {
        return new BigDecimal(value).round(new MathContext(4)).stripTrailingZeros().toPlainString();
    }
}
