package org.kicnp.editor;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.kicnp.core.Change;
import org.kicnp.core.ChangeSet;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Slot;

/**
 * The frame operations of the API: list, read (with effective slots), create, replace with an expected revision,
 * delete and rename. Every change is one knowledge-base batch, so a rejected request changes nothing; the
 * knowledge base's own exceptions travel up to {@link ApiHandler}, which maps them to 404, 409 and 422.
 */
final class FrameResource {
    /** The answer to a change: the knowledge-base version it made and the frame as it now is (if it exists). */
    record Saved(long version, FrameViews.Detail frame) {
    }

    /** The answer to a delete: the version it made, and every frame it removed (the frame, then what rested on it). */
    record Deleted(long version, List<String> removed) {
    }

    private final KnowledgeBase kb;
    private final Features.Inference inference;
    private final Features.Scripts scripts;

    FrameResource(KnowledgeBase kb, Features.Inference inference, Features.Scripts scripts) {
        this.kb = kb;
        this.inference = inference;
        this.scripts = scripts;
    }

    /** Every frame as a row, optionally only those whose name contains {@code q} (case-insensitive). */
    List<FrameViews.Summary> list(Optional<String> q) {
        String needle = q.map(s -> s.toLowerCase(Locale.ROOT)).orElse("");
        return kb.frames().stream()
                .filter(f -> needle.isEmpty() || f.name().toLowerCase(Locale.ROOT).contains(needle))
                .map(f -> FrameViews.summary(kb, f)).toList();
    }

    FrameViews.Detail get(String name) {
        return FrameViews.detail(kb, kb.require(name));
    }

    /** The type {@code parent} or a frame above it declares for slot {@code slot}, if one does. */
    private Optional<DataType> declaredType(String parent, String slot) {
        return kb.contains(parent) ? kb.slot(parent, slot).map(e -> e.slot().type()) : Optional.empty();
    }

    private Optional<String> declaredArgument(String parent, String slot) {
        if (!kb.contains(parent)) {
            return Optional.empty();
        }
        List<String> chain = new ArrayList<>();
        chain.add(parent);
        chain.addAll(kb.ancestors(parent));
        for (String c : chain) {
            Optional<String> a = kb.frame(c).flatMap(f -> f.ownSlot(slot)).flatMap(Slot::argument);
            if (a.isPresent()) {
                return a;
            }
        }
        return Optional.empty();
    }

    /**
     * The frame read, or 422 with every problem: those found reading it, its scripts that do not parse and, for the
     * items read without a problem, those the frame model finds (an unknown argument class, an IS-A cycle, ...), so
     * that one answer lists them all.
     */
    private Frame valid(FrameInput.Read read, Function<Frame, Change> change) {
        List<ApiProblem> scriptProblems = read.frame().map(scripts::problems).orElse(List.of());
        if (read.problems().isEmpty() && scriptProblems.isEmpty()) {
            return read.frame().orElseThrow();
        }
        List<ApiProblem> all = new ArrayList<>(read.problems());
        all.addAll(scriptProblems);
        Set<String> slotsWithProblems = all.stream().map(ApiProblem::slot).filter(s -> !s.isEmpty())
                .collect(Collectors.toSet());
        read.frame().ifPresent(f -> kb.problems(List.of(change.apply(f))).stream().map(ApiProblem::of)
                .filter(p -> !slotsWithProblems.contains(p.slot()) && !all.contains(p)).forEach(all::add));
        throw ApiException.invalid(all);
    }

    Saved create(JsonNode body) {
        Frame f = valid(FrameInput.read(body, Optional.empty(), this::declaredType, this::declaredArgument),
                Change.Add::new);
        ChangeSet cs = kb.apply(List.of(new Change.Add(f)));
        return new Saved(cs.version(), get(f.name()));
    }

    /**
     * Replaces the frame. The body must carry {@code expectedRevision} (the revision the page read) so that a
     * frame someone else saved in between is never silently overwritten.
     */
    Saved replace(String name, JsonNode body) {
        JsonNode rev = body == null ? null : body.get("expectedRevision");
        if (rev == null || !rev.canConvertToLong()) {
            throw new ApiException(400, "Saving frame '" + name + "' needs expectedRevision: the revision you read, "
                    + "so that a change made in between is not overwritten.");
        }
        kb.require(name);
        Frame f = valid(FrameInput.read(body, Optional.of(name), this::declaredType, this::declaredArgument),
                read -> new Change.Replace(read, rev.asLong()));
        ChangeSet cs = kb.apply(List.of(new Change.Replace(f, rev.asLong())));
        return new Saved(cs.version(), get(name));
    }

    /**
     * Deletes a frame. Where an inference engine runs, an instance is destroyed through it, so that the instances
     * derived from it go too (truth maintenance); the knowledge base alone refuses to remove what others refer to.
     */
    Deleted delete(String name) {
        if (kb.require(name).isInstance() && inference.available()) {
            List<String> removed = new ArrayList<>(List.of(name));
            inference.destroy(name).stream().filter(n -> !n.equals(name)).sorted().forEach(removed::add);
            return new Deleted(kb.version(), removed);
        }
        return new Deleted(kb.apply(List.of(new Change.Remove(name))).version(), List.of(name));
    }

    Saved rename(String name, JsonNode body) {
        String to = FrameInput.text(body, "newName").map(String::strip)
                .orElseThrow(() -> new ApiException(400, "Renaming frame '" + name + "' needs newName."));
        if (to.equals(name)) {
            return new Saved(kb.version(), get(name));
        }
        if (kb.contains(to)) {
            throw ApiException.invalid(List.of(ApiProblem.of(name, "", "Frame '" + name + "' cannot be renamed to '"
                    + to + "': a frame of that name already exists.")));
        }
        ChangeSet cs = kb.apply(Renamer.changes(kb, name, to));
        return new Saved(cs.version(), get(to));
    }
}
