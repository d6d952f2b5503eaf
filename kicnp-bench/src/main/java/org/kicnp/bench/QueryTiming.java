package org.kicnp.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;

/**
 * Times {@link KnowledgeBase#instancesOf(String)} on classes at every depth of the generated tree and divides the
 * time by the number of frames returned: the knowledge base promises O(1) per result, whatever the depth.
 * Classes without any instance are left out, since their cost cannot be spread over results.
 */
final class QueryTiming {
    private static final int CLASSES_PER_DEPTH = 32;
    private static final long RESULTS_PER_ROUND = 400_000;
    private static final long WARM_UP_NANOS = 500_000_000L;

    /** The cost per result at one depth, as the median over rounds. */
    record Depth(int depth, int classes, double resultsPerQuery, double usPerResult) {
    }

    /**
     * The overall cost per result by the wall clock, median over rounds, the same by the querying thread's CPU time
     * (NaN when the JVM cannot tell it), and the wall-clock break-down by depth.
     */
    record Result(double usPerResult, double cpuUsPerResult, List<Depth> depths) {
    }

    private final KnowledgeBase kb;
    private final List<Integer> depthNumbers;
    private final List<List<String>> queriesByDepth;
    /** Written with something of every result, so the queries cannot be optimised away. */
    private long sink;

    private QueryTiming(KnowledgeBase kb, List<Integer> depthNumbers, List<List<String>> queriesByDepth) {
        this.kb = kb;
        this.depthNumbers = depthNumbers;
        this.queriesByDepth = queriesByDepth;
    }

    /** Picks up to {@value #CLASSES_PER_DEPTH} classes with instances at each depth of the tree. */
    static QueryTiming over(KnowledgeBase kb, KnowledgeGenerator generator, Random random) {
        List<List<String>> byDepth = new ArrayList<>();
        for (int d = 0; d < KnowledgeGenerator.DEPTH; d++) {
            byDepth.add(new ArrayList<>());
        }
        for (int k = 0; k < generator.classCount(); k++) {
            String name = KnowledgeGenerator.className(k);
            if (kb.countInstancesOf(name) > 0) {
                byDepth.get(generator.depthOf(k)).add(name);
            }
        }
        List<Integer> depths = new ArrayList<>();
        List<List<String>> picked = new ArrayList<>();
        for (int d = 0; d < byDepth.size(); d++) {
            List<String> names = byDepth.get(d);
            Collections.shuffle(names, random);
            if (!names.isEmpty()) {
                depths.add(d);
                picked.add(List.copyOf(names.subList(0, Math.min(CLASSES_PER_DEPTH, names.size()))));
            }
        }
        return new QueryTiming(kb, depths, picked);
    }

    Result measure(int rounds) {
        long warmUpEnd = System.nanoTime() + WARM_UP_NANOS;
        while (System.nanoTime() < warmUpEnd) {
            for (List<String> queries : queriesByDepth) {
                pass(queries);
            }
        }
        List<Samples> perDepth = new ArrayList<>();
        queriesByDepth.forEach(q -> perDepth.add(new Samples()));
        long[] resultsPerPass = queriesByDepth.stream().mapToLong(this::pass).toArray();
        Samples overall = new Samples();
        Samples overallCpu = new Samples();
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        boolean cpuTimed = threads.isCurrentThreadCpuTimeSupported();
        for (int r = 0; r < rounds; r++) {
            long cpuStart = cpuTimed ? threads.getCurrentThreadCpuTime() : 0;
            long nanos = 0;
            long results = 0;
            for (int d = 0; d < queriesByDepth.size(); d++) {
                long reps = Math.max(1, RESULTS_PER_ROUND / resultsPerPass[d]);
                long start = System.nanoTime();
                long got = 0;
                for (long i = 0; i < reps; i++) {
                    got += pass(queriesByDepth.get(d));
                }
                long took = System.nanoTime() - start;
                perDepth.get(d).add(took / 1000.0 / got);
                nanos += took;
                results += got;
            }
            overall.add(nanos / 1000.0 / results);
            if (cpuTimed) {
                overallCpu.add((threads.getCurrentThreadCpuTime() - cpuStart) / 1000.0 / results);
            }
        }
        List<Depth> depths = new ArrayList<>();
        for (int d = 0; d < queriesByDepth.size(); d++) {
            int n = queriesByDepth.get(d).size();
            depths.add(new Depth(depthNumbers.get(d), n, (double) resultsPerPass[d] / n, perDepth.get(d).median()));
        }
        return new Result(overall.median(), overallCpu.size() == 0 ? Double.NaN : overallCpu.median(), depths);
    }

    /** One query on each class; returns the number of results, and keeps them from being optimised away. */
    private long pass(List<String> queries) {
        long results = 0;
        for (String c : queries) {
            List<Frame> found = kb.instancesOf(c);
            results += found.size();
            sink += found.get(found.size() - 1).name().length();
        }
        return results;
    }
}
