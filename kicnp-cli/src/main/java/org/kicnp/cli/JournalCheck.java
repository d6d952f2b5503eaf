package org.kicnp.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeException;
import org.kicnp.core.store.KnowledgeStore;
import org.kicnp.core.store.StoreOptions;
import org.kicnp.core.xml.LoadError;
import org.kicnp.core.xml.SourceLocation;
import org.kicnp.core.xml.SourcedFrame;

/**
 * What {@code validate} adds for a knowledge directory whose store journal still holds changes: it opens the
 * directory as {@code serve} does ({@link KnowledgeStore#open}: the XML files with the journal replayed on top), so
 * the frames checked are the frames the platform would run with. The store is opened without compacting, so the
 * files and the journal are left as they were (only what any open does after a crash, finishing an interrupted
 * compaction or cutting a torn last record, may happen).
 */
final class JournalCheck {
    private static final StoreOptions READ_ONLY = StoreOptions.defaults().withCompactInBackground(false)
            .withCompactOnClose(false).withCompactAfterRecords(Integer.MAX_VALUE).withCompactAfterBytes(Long.MAX_VALUE);

    /** The outcome: the frames as the platform would open them, or the errors that stop the open. */
    record Result(boolean opened, List<Frame> frames, String summary, List<LoadError> errors) {
    }

    private JournalCheck() {
    }

    /** Opens {@code dir} as the platform would and compares its frames with {@code fromFiles}, the XML files alone. */
    static Result check(Path dir, List<SourcedFrame> fromFiles) {
        Path meta = dir.resolve(KnowledgeStore.META_DIR);
        try (KnowledgeStore store = KnowledgeStore.open(dir, READ_ONLY)) {
            int records = store.journalRecords();
            List<Frame> frames = store.kb().frames().stream().toList();
            Map<String, Frame> files = fromFiles.stream().map(SourcedFrame::frame)
                    .filter(f -> f.provenance().durable())
                    .collect(Collectors.toMap(Frame::name, Function.identity(), (a, b) -> b));
            int added = 0;
            int changed = 0;
            List<SourcedFrame> fromJournal = new ArrayList<>();
            for (Frame f : frames) {
                Optional<Frame> before = Optional.ofNullable(files.remove(f.name()));
                if (!f.provenance().durable() || before.map(f::equals).orElse(false)) {
                    continue;
                }
                if (before.isPresent()) {
                    changed++;
                } else {
                    added++;
                }
                fromJournal.add(new SourcedFrame(f, new SourceLocation(meta.toString(), 0, 0)));
            }
            String summary = "Journal: " + meta + " holds " + plural(records, "record") + " not yet folded into the "
                    + "files; replayed on top of them, as serve would open the directory (" + plural(added, "frame")
                    + " added, " + changed + " changed, " + files.size() + " removed).";
            return new Result(true, frames, summary, ScriptSyntaxCheck.errors(fromJournal));
        } catch (KnowledgeException e) { // StoreException included: a damaged journal, a locked or unreadable store
            String message = e.getMessage().replaceAll("\\R\\s*", " ");
            return new Result(false, List.of(), "Journal: " + meta + " could not be replayed onto the knowledge files.",
                    List.of(new LoadError(meta.toString(), 0, 0, message)));
        }
    }

    static String plural(long n, String one) {
        return n + " " + (n == 1 ? one : one + "s");
    }
}
