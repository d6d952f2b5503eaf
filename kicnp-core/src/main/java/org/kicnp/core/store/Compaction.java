package org.kicnp.core.store;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;
import org.kicnp.core.Frame;
import org.kicnp.core.xml.KnowledgeXmlWriter;

/**
 * Writes new contents of XML files crash-safely: every new file goes to a temporary file beside its target and is
 * forced to disk; then the {@link Manifest} is written; then the temporary files are renamed over their targets.
 * A crash before the manifest leaves the old files and stray temporary files (deleted at open); a crash after it
 * leaves a manifest that open finishes. Either way every XML file is complete, old or new. A new file takes the
 * permissions of the one it replaces, and a knowledge file that is a symbolic link is rewritten where it points.
 */
final class Compaction {
    static final String TEMP_SUFFIX = ".kicnp-tmp";

    private Compaction() {
    }

    /**
     * Replaces each file with its new frames; a file whose list is empty is deleted.
     *
     * @param contents new contents by path relative to {@code dir}
     */
    static void write(Path dir, Path kicnpDir, Map<Path, List<Frame>> contents, Disk disk) throws IOException {
        List<Manifest.Entry> entries = new ArrayList<>();
        Set<Path> tempDirs = new LinkedHashSet<>();
        for (var e : contents.entrySet()) {
            Path target = e.getKey();
            if (e.getValue().isEmpty()) {
                entries.add(new Manifest.Delete(target));
                continue;
            }
            Path real = inPlace(dir, target);
            Path temp = real.resolveSibling(real.getFileName() + TEMP_SUFFIX);
            Path absolute = dir.resolve(temp);
            Files.createDirectories(absolute.getParent());
            writeForced(absolute, e.getValue(), disk);
            keepPermissions(dir.resolve(real), absolute);
            tempDirs.add(absolute.getParent());
            entries.add(new Manifest.Rename(temp, real));
        }
        for (Path d : tempDirs) {
            disk.syncDirectory(d);
        }
        Manifest manifest = new Manifest(entries);
        manifest.write(kicnpDir, disk);
        manifest.complete(dir, disk);
    }

    /**
     * Where {@code target} (relative to {@code dir}) is really written: a knowledge file that is a symbolic link is
     * rewritten at the file it points to (its temporary file beside that one, so the rename stays in one directory),
     * and the link stays a link. The path is relative to {@code dir} when the file lies inside it, else absolute.
     */
    private static Path inPlace(Path dir, Path target) throws IOException {
        Path absolute = dir.resolve(target);
        if (!Files.isSymbolicLink(absolute) || !Files.exists(absolute)) {
            return target; // a dangling link is replaced like a missing file
        }
        Path real = absolute.toRealPath();
        Path realDir = dir.toRealPath();
        return real.startsWith(realDir) ? realDir.relativize(real) : real;
    }

    /** Gives the new file the permissions of the one it replaces, rather than the process's defaults. */
    private static void keepPermissions(Path replaced, Path temp) throws IOException {
        if (!Files.exists(replaced)) {
            return;
        }
        try {
            Files.setPosixFilePermissions(temp, Files.getPosixFilePermissions(replaced));
        } catch (UnsupportedOperationException notPosix) {
            // A file system without POSIX permissions (Windows): nothing to keep.
        }
    }

    private static void writeForced(Path file, List<Frame> frames, Disk disk) throws IOException {
        try (FileChannel ch = FileChannel.open(file, StandardOpenOption.CREATE, StandardOpenOption.WRITE,
                StandardOpenOption.TRUNCATE_EXISTING)) {
            StringWriter text = new StringWriter(4096);
            KnowledgeXmlWriter.write(frames, text);
            ByteBuffer bytes = StandardCharsets.UTF_8.encode(text.toString());
            while (bytes.hasRemaining()) {
                ch.write(bytes);
            }
            disk.force(ch);
        }
    }

    /** Deletes temporary files that no manifest names: the leftovers of a compaction that crashed before its manifest. */
    static void deleteStrayTemps(Path dir, Path kicnpDir) throws IOException {
        List<Path> stray;
        try (Stream<Path> all = Files.walk(dir)) {
            stray = all.filter(p -> !p.startsWith(kicnpDir) && p.getFileName().toString().endsWith(TEMP_SUFFIX)
                    && Files.isRegularFile(p)).toList();
        }
        for (Path p : stray) {
            Files.deleteIfExists(p);
        }
        Files.deleteIfExists(kicnpDir.resolve(Manifest.FILE + ".tmp"));
    }
}
