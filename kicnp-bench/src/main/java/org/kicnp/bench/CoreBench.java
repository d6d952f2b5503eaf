package org.kicnp.bench;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.lang.ref.Reference;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.List;
import java.util.Random;
import java.util.concurrent.Callable;
import java.util.stream.Stream;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.xml.KnowledgeLoader;
import org.kicnp.core.xml.KnowledgeXmlException;
import org.kicnp.core.xml.KnowledgeXmlWriter;
import org.kicnp.core.xml.LoadError;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * {@code ./kicnp bench core}: the knowledge core on a large generated knowledge base. Saves it as XML, loads it
 * back into a fresh knowledge base, and measures load time, save time, the heap the loaded knowledge base
 * retains, and the cost per result of {@code instancesOf}. Untimed warm-up rounds come first; times are the
 * median of the timed rounds.
 */
@Command(name = "core",
        mixinStandardHelpOptions = true,
        description = {
            "Knowledge core: XML load and save time, retained heap, instancesOf cost per result.",
            "Generates a knowledge base (IS-A tree 8 deep, 6 slots per frame, a third instances), saves it as XML,",
            "loads it back into a fresh knowledge base, and measures; times are medians of the timed rounds.",
            "Then adds --adds small instance frames one apply each, as rule firings do, and times one add.",
            "The last line of output is one JSON object with the figures."
        })
final class CoreBench implements Callable<Integer> {
    /** Timed rounds of the one-apply-per-instance adds; each is long enough to be steady. */
    private static final int ADD_ROUNDS = 3;

    @Spec
    CommandSpec spec;

    @Option(names = "--frames", defaultValue = "100000", description = "Frames to generate (default: ${DEFAULT-VALUE}).")
    int frames;

    @Option(names = "--warmup", defaultValue = "2", description = "Untimed load/save rounds first (default: ${DEFAULT-VALUE}).")
    int warmup;

    @Option(names = "--rounds", defaultValue = "5", description = "Timed rounds; the median is reported (default: ${DEFAULT-VALUE}).")
    int rounds;

    @Option(names = "--seed", defaultValue = "42", description = "Seed of the generator (default: ${DEFAULT-VALUE}).")
    long seed;

    @Option(names = "--adds", defaultValue = "300000",
            description = "Instances added one apply each, as rule firings add them (default: ${DEFAULT-VALUE}).")
    int adds;

    @Override public Integer call() throws IOException {
        if (frames < 3 || warmup < 0 || rounds < 1 || adds < 1) {
            throw new ParameterException(spec.commandLine(),
                    "Need --frames of at least 3, --warmup of 0 or more, --rounds of 1 or more and --adds of 1 or more.");
        }
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        Path dir = Files.createTempDirectory("kicnp-bench-core");
        try {
            return run(dir, out, err);
        } catch (KnowledgeXmlException e) {
            List<LoadError> errors = e.errors();
            errors.stream().limit(20).forEach(x -> err.println(x.format()));
            err.printf("The generated knowledge base did not load back (%d errors); no figures.%n", errors.size());
            return 1;
        } finally {
            deleteTree(dir);
            out.flush();
            err.flush();
        }
    }

    private int run(Path dir, PrintWriter out, PrintWriter err) throws IOException {
        KnowledgeGenerator generator = KnowledgeGenerator.of(frames, seed);
        Path source = Files.createDirectories(dir.resolve("source"));
        Path saved = dir.resolve("saved.xml");
        progress(err, "Generating %d frames and writing them to %s", frames, source);
        long bytes = writeGenerated(generator, source.resolve("knowledge.xml"));

        progress(err, "Warming up: %d untimed load/save rounds", warmup);
        for (int i = 0; i < warmup; i++) {
            save(load(source), saved);
        }
        Timed loads = new Timed();
        Timed saves = new Timed();
        for (int i = 0; i < rounds; i++) {
            progress(err, "Timed round %d of %d", i + 1, rounds);
            timedRound(loads, saves, source, saved);
        }

        progress(err, "Measuring the retained heap of one loaded knowledge base");
        long before = HeapMeter.usedAfterGc();
        KnowledgeBase kb = load(source);
        long after = HeapMeter.usedAfterGc();
        Reference.reachabilityFence(kb);
        double heapMb = (after - before) / (1024.0 * 1024.0);

        progress(err, "Checking the loaded frames against a fresh generation with the same seed");
        verify(kb, saved);

        progress(err, "Timing instancesOf on classes at every depth");
        QueryTiming timing = QueryTiming.over(kb, generator, new Random(seed));
        QueryTiming.Result query = timing.measure(rounds);

        progress(err, "Adding %d instances one apply each", adds);
        AddTiming.Result added = AddTiming.measure(adds, ADD_ROUNDS);

        new CoreReport(frames, generator.classCount(), generator.instanceCount(), bytes, warmup, rounds,
                loads, saves, heapMb, query, added).print(out);
        return 0;
    }

    /**
     * One timed load and save, in a method of its own: the knowledge base is unreachable once it returns, so the next
     * round's load does not run with the last one's still alive (a local in the loop would keep it, and every young
     * collection during the load would copy it). A {@code System.gc()} first, as the inference bench does before
     * each run, so a round does not pay for collecting the garbage of the one before; collections the load's own
     * allocation makes are timed.
     */
    private void timedRound(Timed loads, Timed saves, Path source, Path saved) {
        System.gc();
        KnowledgeBase kb = loads.time(() -> load(source));
        saves.time(() -> save(kb, saved));
    }

    /** Generates and writes the frames; they are unreachable once this returns, so they do not skew the heap. */
    private static long writeGenerated(KnowledgeGenerator generator, Path file) throws IOException {
        List<Frame> generated = generator.generate();
        KnowledgeXmlWriter.write(generated, file);
        return Files.size(file);
    }

    private KnowledgeBase load(Path source) {
        KnowledgeBase kb = KnowledgeBase.create();
        KnowledgeLoader.load(kb, List.of(source));
        if (kb.size() != frames) {
            throw new IllegalStateException("The knowledge base loaded back holds " + kb.size() + " frames, not "
                    + frames + ": the benchmark would measure the wrong thing.");
        }
        return kb;
    }

    /**
     * Guards against measuring a load that lost or changed something: every 97th generated frame, and the last,
     * must be equal, in the same place, in the knowledge base loaded from the generated file and in one loaded
     * from the file the benchmark saved.
     */
    private void verify(KnowledgeBase kb, Path saved) {
        List<Frame> expected = KnowledgeGenerator.of(frames, seed).generate();
        List<Frame> fromSource = kb.frames();
        List<Frame> fromSaved = load(saved).frames();
        for (int i = 0; i < expected.size(); i = i == expected.size() - 1 ? expected.size()
                : Math.min(i + 97, expected.size() - 1)) {
            Frame want = expected.get(i);
            if (!want.equals(fromSource.get(i)) || !want.equals(fromSaved.get(i))) {
                throw new IllegalStateException("Frame " + i + " ('" + want.name() + "') did not load back as it "
                        + "was generated: the benchmark would measure the wrong thing.");
            }
        }
    }

    private static KnowledgeBase save(KnowledgeBase kb, Path file) {
        KnowledgeXmlWriter.write(kb.frames(), file);
        return kb;
    }

    private static void progress(PrintWriter err, String format, Object... args) {
        err.printf("[bench core] " + format + "%n", args);
        err.flush();
    }

    private static void deleteTree(Path dir) {
        try (Stream<Path> paths = Files.walk(dir)) {
            paths.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        } catch (IOException | UncheckedIOException e) {
            // A temporary directory left behind is harmless; the figures are what matter.
        }
    }
}
