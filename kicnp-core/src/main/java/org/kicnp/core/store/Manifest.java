package org.kicnp.core.store;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;

/**
 * The file moves of one compaction, written to {@code .kicnp/compaction} once every new file is complete on disk
 * and before any of them replaces its target. Its presence at open means "finish these moves": each move is
 * idempotent (a rename whose temporary file is gone has happened; deleting a missing file does nothing), so a
 * crash while finishing them is finished again next time. The manifest itself appears atomically, by rename.
 *
 * @param entries the moves, with paths relative to the store directory
 */
record Manifest(List<Entry> entries) {
    static final String FILE = "compaction";
    private static final String HEADER = "kicnp-compaction 1";
    private static final String END = "end";

    Manifest {
        entries = List.copyOf(entries);
    }

    /** One file move. */
    sealed interface Entry permits Rename, Delete {
    }

    /** Replace {@code target} with the finished {@code temp}. */
    record Rename(Path temp, Path target) implements Entry {
    }

    /** Remove {@code target}, whose frames are all gone. */
    record Delete(Path target) implements Entry {
    }

    /** Writes the manifest to a temporary name, forces it, renames it into place and forces the directory. */
    void write(Path kicnpDir, Disk disk) throws IOException {
        StringBuilder text = new StringBuilder(HEADER).append('\n');
        for (Entry e : entries) {
            switch (e) {
                case Rename r -> text.append("rename\t").append(slashes(r.temp())).append('\t')
                        .append(slashes(r.target())).append('\n');
                case Delete d -> text.append("delete\t").append(slashes(d.target())).append('\n');
            }
        }
        text.append(END).append('\n');
        Path tmp = kicnpDir.resolve(FILE + ".tmp");
        try (FileChannel ch = FileChannel.open(tmp, StandardOpenOption.CREATE, StandardOpenOption.WRITE,
                StandardOpenOption.TRUNCATE_EXISTING)) {
            ch.write(StandardCharsets.UTF_8.encode(text.toString()));
            disk.force(ch);
        }
        Files.move(tmp, kicnpDir.resolve(FILE), StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        disk.syncDirectory(kicnpDir);
    }

    /** The manifest left by an unfinished compaction, if there is one. */
    static Optional<Manifest> read(Path kicnpDir) throws IOException {
        Path file = kicnpDir.resolve(FILE);
        if (!Files.exists(file)) {
            return Optional.empty();
        }
        List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        if (lines.size() < 2 || !lines.get(0).equals(HEADER) || !lines.get(lines.size() - 1).equals(END)) {
            throw new StoreException("The compaction manifest '" + file + "' is not complete; it is written by "
                    + "rename, so this is not crash damage. Inspect it and the '*.kicnp-tmp' files by hand.");
        }
        List<Entry> entries = new ArrayList<>();
        for (String line : lines.subList(1, lines.size() - 1)) {
            String[] f = line.split("\t");
            if (f.length == 3 && f[0].equals("rename")) {
                entries.add(new Rename(Path.of(f[1]), Path.of(f[2])));
            } else if (f.length == 2 && f[0].equals("delete")) {
                entries.add(new Delete(Path.of(f[1])));
            } else {
                throw new StoreException("The compaction manifest '" + file + "' has a line it does not understand: '"
                        + line + "'.");
            }
        }
        return Optional.of(new Manifest(entries));
    }

    /** Performs every move (again, if some already happened) and forces the directories involved. */
    void complete(Path dir, Disk disk) throws IOException {
        Set<Path> touched = new LinkedHashSet<>();
        for (Entry e : entries) {
            switch (e) {
                case Rename r -> {
                    Path temp = dir.resolve(r.temp());
                    if (Files.exists(temp)) {
                        Files.move(temp, dir.resolve(r.target()), StandardCopyOption.ATOMIC_MOVE,
                                StandardCopyOption.REPLACE_EXISTING);
                    }
                    touched.add(dir.resolve(r.target()).getParent());
                }
                case Delete d -> {
                    Files.deleteIfExists(dir.resolve(d.target()));
                    touched.add(dir.resolve(d.target()).getParent());
                }
            }
        }
        for (Path p : touched) {
            disk.syncDirectory(p);
        }
    }

    /** Removes the manifest once its moves are durable and the journal segments it folded are gone. */
    static void remove(Path kicnpDir, Disk disk) throws IOException {
        Files.deleteIfExists(kicnpDir.resolve(FILE));
        disk.syncDirectory(kicnpDir);
    }

    private static String slashes(Path p) {
        String s = p.toString().replace('\\', '/');
        if (s.contains("\t") || s.contains("\n")) {
            throw new StoreException("The knowledge file name '" + s + "' contains a tab or a line break, which the "
                    + "store cannot record.");
        }
        return s;
    }
}
