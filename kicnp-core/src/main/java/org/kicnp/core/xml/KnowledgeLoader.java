package org.kicnp.core.xml;

import static java.util.Objects.requireNonNull;

import java.io.IOException;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.Function;
import java.util.function.IntFunction;
import org.kicnp.core.BatchRejectedException;
import org.kicnp.core.Change;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Problem;
import org.kicnp.core.StagedBatch;

/**
 * Reads knowledge files in the paper's XML format (Table 4) and loads them into a {@link KnowledgeBase}. All files of
 * one call are read and mapped together, so a frame may name a parent defined in another file; they are added in one
 * {@link StagedBatch}, which checks the frames part by part while reading goes on and applies them all at the end, so
 * a load either adds every frame or changes nothing. Every error is reported with its file, line and
 * column in one {@link KnowledgeXmlException}.
 */
public final class KnowledgeLoader {
    /** What an empty path, which Java would take for the working directory, is told. */
    public static final String EMPTY_PATH = "An empty path names no file or directory; write '.' for the current "
            + "directory.";
    /** Inputs larger than this are mapped on a second thread while they are read. */
    static final long PIPELINE_CHARS = 4L * 1024 * 1024;

    private KnowledgeLoader() {
    }

    /**
     * The knowledge files named by the arguments: a file stands for itself, a directory for every {@code *.xml}
     * file below it (recursively, sorted by path, skipping hidden files and directories such as {@code .kicnp};
     * a symbolic link to a file counts as that file, a link to a directory is not followed).
     *
     * @throws KnowledgeXmlException naming every path that does not exist, and any empty path
     */
    public static List<Path> expand(List<Path> filesOrDirs) {
        requireNonNull(filesOrDirs, "filesOrDirs");
        List<Path> out = new ArrayList<>();
        List<LoadError> errors = new ArrayList<>();
        Set<Path> seen = new HashSet<>();
        for (Path p : filesOrDirs) {
            if (p.toString().isEmpty()) {
                // Path.of("") is the working directory: an empty argument (an unset shell variable) would load it.
                errors.add(new LoadError("''", 1, 1, EMPTY_PATH));
            } else if (Files.isDirectory(p)) {
                for (Path f : xmlFilesBelow(p, errors)) {
                    if (seen.add(f.toAbsolutePath().normalize())) {
                        out.add(f);
                    }
                }
            } else if (Files.isRegularFile(p)) {
                if (seen.add(p.toAbsolutePath().normalize())) {
                    out.add(p);
                }
            } else {
                errors.add(new LoadError(p.toString(), 1, 1, "No such file or directory: '" + p + "'."));
            }
        }
        if (!errors.isEmpty()) {
            throw new KnowledgeXmlException(errors);
        }
        return out;
    }

    /**
     * Reads and maps the frames of all the files without changing anything. Slots that leave out their TYPE take it
     * from the nearest declaration up the ISA chain, among the frames being read and then in {@code context}.
     *
     * @throws KnowledgeXmlException listing every error found
     */
    public static List<SourcedFrame> parse(List<Path> filesOrDirs, KnowledgeBase context) {
        return sourced(parseFiles(filesOrDirs, context, null, null));
    }

    /**
     * Reads frames from text, such as a frame sent over the network or saved in the editor.
     *
     * @param sourceName what errors name as the source, e.g. {@code editor}
     * @throws KnowledgeXmlException listing every error found
     */
    public static List<SourcedFrame> parseText(String xml, String sourceName, KnowledgeBase context) {
        return parseText(xml, sourceName, context, null);
    }

    /**
     * Reads frames from text that the caller is to put (add, or replace where the name exists) into {@code kb} in
     * one batch, as the editor's import does. When some frames have errors in the XML, the others are checked as
     * such a batch would be and their problems reported with the errors, as {@link #load} does.
     *
     * @throws KnowledgeXmlException listing every error found
     */
    public static List<SourcedFrame> parseTextToPut(String xml, String sourceName, KnowledgeBase kb) {
        requireNonNull(kb, "kb");
        return parseText(xml, sourceName, kb, frames -> {
            List<Change> puts = new ArrayList<>(frames.size());
            frames.forEach(f -> puts.add(new Change.Put(f)));
            return kb.problems(puts);
        });
    }

    /**
     * Reads frames from text written against a state that {@code context} does not hold: the frames above those read
     * (whose declarations, such as a list slot's ARGUMENT, they inherit) are looked up with {@code above} instead. The
     * knowledge store reads a journal record so, against the frames as the records before it left them.
     *
     * @throws KnowledgeXmlException listing every error found
     */
    public static List<SourcedFrame> parseTextAbove(String xml, String sourceName, KnowledgeBase context,
            Function<String, Optional<Frame>> above) {
        requireNonNull(above, "above");
        return parseChecked(List.of(xml), i -> sourceName, context, above, null);
    }

    /**
     * Reads several texts as one set, as {@link #parse} reads several files: a frame inherits declarations from the
     * frames of every text, then from {@code context}, and a name defined twice is an error. Frames sent one text
     * each (a push, the answer to a pull) are read so, whatever their order.
     *
     * @param sourceName what errors name as the source of the text at each index
     * @throws KnowledgeXmlException listing every error found
     */
    public static List<SourcedFrame> parseTexts(List<String> texts, IntFunction<String> sourceName,
            KnowledgeBase context) {
        requireNonNull(context, "context");
        return parseChecked(texts, sourceName, context, context::frame, null);
    }

    private static List<SourcedFrame> parseText(String xml, String sourceName, KnowledgeBase context,
            Function<List<Frame>, List<Problem>> check) {
        requireNonNull(context, "context");
        return parseChecked(List.of(requireNonNull(xml, "xml")), i -> sourceName, context, context::frame, check);
    }

    private static List<SourcedFrame> parseChecked(List<String> texts, IntFunction<String> sourceName,
            KnowledgeBase context, Function<String, Optional<Frame>> above, Function<List<Frame>, List<Problem>> check) {
        requireNonNull(texts, "texts");
        requireNonNull(sourceName, "sourceName");
        requireNonNull(context, "context");
        long chars = 0;
        for (String t : texts) {
            chars += requireNonNull(t, "text").length();
        }
        LoadSession session = new LoadSession(context, above, chars > PIPELINE_CHARS, null, check);
        try {
            for (int i = 0; i < texts.size(); i++) {
                session.readText(texts.get(i), requireNonNull(sourceName.apply(i), "sourceName"));
            }
            return sourced(session.finish());
        } finally {
            session.abandon();
        }
    }

    /**
     * Reads all the files and adds their frames to {@code kb} in one batch. On any error (in the XML, in a value, or
     * against the frame model, such as an unknown parent or an IS-A cycle) nothing is added. When some frames have
     * errors in the XML, the others are still checked against the frame model and their problems reported too,
     * except those that may only follow from a frame with errors (see {@link LoadSession}).
     *
     * @return the frames added, in file order
     * @throws KnowledgeXmlException listing every error, each at the element it concerns
     */
    public static List<SourcedFrame> load(KnowledgeBase kb, List<Path> filesOrDirs) {
        requireNonNull(kb, "kb");
        // Frames go to the batch as they are mapped, so the knowledge base checks them while the files are read.
        StagedBatch batch = kb.stagedBatch();
        List<ParsedFrame> parsed = parseFiles(filesOrDirs, kb, batch, frames -> {
            List<Change> adds = new ArrayList<>(frames.size());
            frames.forEach(f -> adds.add(new Change.Add(f)));
            return kb.problems(adds);
        });
        try {
            batch.commit();
        } catch (BatchRejectedException e) {
            throw locate(e, parsed);
        }
        return sourced(parsed);
    }

    private static List<ParsedFrame> parseFiles(List<Path> filesOrDirs, KnowledgeBase context, StagedBatch target,
            Function<List<Frame>, List<Problem>> check) {
        requireNonNull(context, "context");
        List<Path> files = expand(filesOrDirs);
        long bytes = 0;
        for (Path f : files) {
            try {
                bytes += Files.size(f);
            } catch (IOException e) {
                // Reported with its location when the file is read.
            }
        }
        LoadSession session = new LoadSession(context, bytes > PIPELINE_CHARS, target, check);
        try {
            for (Path f : files) {
                session.readFile(f);
            }
            return session.finish();
        } finally {
            session.abandon();
        }
    }

    /** Points each problem of a rejected batch at the element it concerns: the slot, the ISA, or the frame. */
    private static KnowledgeXmlException locate(BatchRejectedException e, List<ParsedFrame> parsed) {
        Map<String, ParsedFrame> byName = new HashMap<>(parsed.size() * 2);
        for (ParsedFrame p : parsed) {
            byName.put(p.sourced().frame().name(), p);
        }
        List<LoadError> errors = new ArrayList<>(e.problems().size());
        for (Problem problem : e.problems()) {
            errors.add(locate(problem, byName.get(problem.frame())));
        }
        errors.sort(java.util.Comparator.comparing(LoadError::source).thenComparingInt(LoadError::line)
                .thenComparingInt(LoadError::column));
        return new KnowledgeXmlException(errors, sourced(parsed));
    }

    /**
     * A problem of the frame model at the element it concerns: the slot, the ISA, or the frame.
     *
     * @param p the frame the problem is about, or null when it was not read
     */
    static LoadError locate(Problem problem, ParsedFrame p) {
        SourceLocation at;
        if (p == null) {
            at = new SourceLocation("(knowledge base)", 1, 1);
        } else if (problem.slot().isPresent()) {
            at = p.slot(problem.slot().get());
        } else if (problem.message().contains("' is a kind of '") && p.isa().isPresent()) {
            at = p.isa().get();
        } else {
            at = p.sourced().location();
        }
        return LoadError.at(at, problem);
    }

    private static List<SourcedFrame> sourced(List<ParsedFrame> parsed) {
        List<SourcedFrame> out = new ArrayList<>(parsed.size());
        for (ParsedFrame p : parsed) {
            out.add(p.sourced());
        }
        return List.copyOf(out);
    }

    private static List<Path> xmlFilesBelow(Path dir, List<LoadError> errors) {
        List<Path> files = new ArrayList<>();
        try {
            Files.walkFileTree(dir, new SimpleFileVisitor<>() {
                @Override public FileVisitResult preVisitDirectory(Path d, BasicFileAttributes attrs) {
                    return !d.equals(dir) && hidden(d) ? FileVisitResult.SKIP_SUBTREE : FileVisitResult.CONTINUE;
                }

                @Override public FileVisitResult visitFile(Path f, BasicFileAttributes attrs) {
                    String name = f.getFileName().toString();
                    // A file linked in (a symbolic link to a regular file) is a knowledge file too; linked directories
                    // are not followed, so a link cannot make the walk loop.
                    boolean file = attrs.isRegularFile() || attrs.isSymbolicLink() && Files.isRegularFile(f);
                    if (file && name.endsWith(".xml") && !hidden(f)) {
                        files.add(f);
                    }
                    return FileVisitResult.CONTINUE;
                }
            });
        } catch (IOException e) {
            errors.add(new LoadError(dir.toString(), 1, 1, "The directory cannot be read: " + e.getMessage() + "."));
        }
        files.sort(null);
        return files;
    }

    private static boolean hidden(Path p) {
        return p.getFileName() != null && p.getFileName().toString().startsWith(".");
    }
}
