package org.kicnp.cli;

import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.kicnp.core.Frame;
import org.kicnp.core.FrameKind;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.store.KnowledgeStore;
import org.kicnp.core.xml.KnowledgeLoader;
import org.kicnp.core.xml.KnowledgeXmlException;
import org.kicnp.core.xml.LoadError;
import org.kicnp.core.xml.SourcedFrame;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code kicnp validate}: loads knowledge files together, as one knowledge base, and reports every error with
 * its place. A frame in one file may name its parent in another, so the files are checked as a whole, not one
 * by one. Errors go to stdout one per line as {@code FILE:LINE:COLUMN: message}, the form editors and
 * {@code grep} understand. A directory whose store journal still holds changes (a server that did not shut down
 * cleanly) is checked as {@code serve} would open it, the journal replayed on top of the files.
 */
@Command(name = "validate",
        mixinStandardHelpOptions = true,
        description = {
            "Loads the knowledge files (XML, in the paper's format) together as one knowledge base and checks them.",
            "Directories are searched for *.xml files; scripts are parsed (never run). Prints OK with the counts, or",
            "each error on a line of its own:",
            "  FILE:LINE:COLUMN: message",
            "A directory whose journal (DIR/.kicnp) still holds changes is checked as serve would open it: the files",
            "with the journal replayed on top; its errors are placed at DIR/.kicnp:0:0."
        },
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {
            "0:every file loaded",
            "1:an error in a file, or a path that does not exist",
            "2:wrong usage"
        })
public final class ValidateCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(arity = "1..*", paramLabel = "FILE_OR_DIR",
            description = "Knowledge files, or directories holding them, loaded together.")
    List<Path> paths;

    @Override public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        try {
            return validate(out);
        } finally {
            out.flush();
        }
    }

    private int validate(PrintWriter out) {
        // An empty argument would be the working directory to Files.exists and expand.
        List<Path> missing = paths.stream().filter(p -> p.toString().isEmpty() || !Files.exists(p)).toList();
        if (!missing.isEmpty()) {
            missing.forEach(p -> out.println(p.toString().isEmpty() ? "'': " + KnowledgeLoader.EMPTY_PATH
                    : p + ": no such file or directory."));
            out.println("FAILED: " + plural(missing.size(), "path") + " not found; nothing was loaded.");
            return 1;
        }
        List<Path> files;
        try {
            files = KnowledgeLoader.expand(paths);
        } catch (UncheckedIOException e) {
            out.println("FAILED: the knowledge files could not be listed: " + e.getCause().getMessage());
            return 1;
        } catch (KnowledgeXmlException e) { // a path removed since it was looked at, or a directory not readable
            e.errors().forEach(err -> out.println(err.format()));
            out.println("FAILED: the knowledge files could not be listed; nothing was loaded.");
            return 1;
        }
        if (files.isEmpty()) {
            out.println("FAILED: no knowledge files (*.xml) found in " + paths + ".");
            return 1;
        }
        try {
            List<SourcedFrame> loaded = KnowledgeLoader.load(KnowledgeBase.create(), files);
            List<LoadError> scriptErrors = ScriptSyntaxCheck.errors(loaded);
            if (!scriptErrors.isEmpty()) {
                return failed(out, scriptErrors, files, "");
            }
            List<Path> journaled = paths.stream().filter(Files::isDirectory).filter(KnowledgeStore::hasPendingChanges).toList();
            if (paths.size() == 1 && journaled.size() == 1) {
                return withJournal(out, journaled.get(0), loaded, files);
            }
            journaled.forEach(d -> out.println("Journal: " + d.resolve(KnowledgeStore.META_DIR) + " holds changes not "
                    + "yet folded into the files, which were not replayed: serve opens one directory, so validate "
                    + d + " alone to check them."));
            printOk(out, loaded.stream().map(SourcedFrame::frame).toList(), files, "");
            return 0;
        } catch (KnowledgeXmlException e) {
            // The scripts of the frames that were read are checked too, so one run reports every error.
            List<LoadError> all = new ArrayList<>(e.errors());
            all.addAll(ScriptSyntaxCheck.errors(e.framesRead()));
            Map<String, Integer> order = new HashMap<>();
            files.forEach(f -> order.putIfAbsent(f.toString(), order.size()));
            all.sort(Comparator.comparingInt((LoadError err) -> order.getOrDefault(err.source(), Integer.MAX_VALUE))
                    .thenComparingInt(LoadError::line).thenComparingInt(LoadError::column));
            return failed(out, all, files, "");
        } catch (UncheckedIOException e) {
            out.println("FAILED: a knowledge file could not be read: " + e.getCause().getMessage());
            return 1;
        }
    }

    /** Validates what {@code serve} would open: the files of {@code dir} with its journal replayed on top. */
    private static int withJournal(PrintWriter out, Path dir, List<SourcedFrame> loaded, List<Path> files) {
        JournalCheck.Result journal = JournalCheck.check(dir, loaded);
        out.println(journal.summary());
        if (!journal.opened()) {
            journal.errors().forEach(err -> out.println(err.format()));
            out.println("FAILED: the journal does not replay onto the knowledge files.");
            return 1;
        }
        if (!journal.errors().isEmpty()) {
            return failed(out, journal.errors(), files, " and the journal");
        }
        printOk(out, journal.frames(), files, " and the journal");
        return 0;
    }

    private static void printOk(PrintWriter out, List<Frame> frames, List<Path> files, String andJournal) {
        long instances = frames.stream().filter(f -> f.kind() == FrameKind.INSTANCE).count();
        out.printf("OK: %s (%s, %s) from %s%s%n", plural(frames.size(), "frame"),
                plural(frames.size() - instances, "class", "classes"), plural(instances, "instance"),
                plural(files.size(), "file"), andJournal);
    }

    private static int failed(PrintWriter out, List<LoadError> errors, List<Path> files, String andJournal) {
        // One error per line, whatever the message holds, so the output stays grep-able.
        errors.forEach(err -> out.println(err.format().replaceAll("\\R\\s*", " ")));
        long sources = errors.stream().map(LoadError::source).distinct().count();
        out.printf("FAILED: %s in %s (of %s checked%s)%n", plural(errors.size(), "error"),
                plural(sources, "file"), plural(files.size(), "file"), andJournal);
        return 1;
    }

    private static String plural(long n, String one) {
        return plural(n, one, one + "s");
    }

    private static String plural(long n, String one, String many) {
        return n + " " + (n == 1 ? one : many);
    }
}
