package org.kicnp.editor;

import static java.util.Objects.requireNonNull;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.kicnp.core.BatchRejectedException;
import org.kicnp.core.Change;
import org.kicnp.core.ChangeSet;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Problem;
import org.kicnp.core.xml.KnowledgeLoader;
import org.kicnp.core.xml.KnowledgeXmlException;
import org.kicnp.core.xml.KnowledgeXmlWriter;
import org.kicnp.core.xml.LoadError;
import org.kicnp.core.xml.SourceLocation;
import org.kicnp.core.xml.SourcedFrame;

/**
 * Export and import in the paper's XML format (Table 4), through the core's reader and writer. Export writes the
 * durable frames (declared and learned; runtime frames are not knowledge to keep). Import is all or nothing: the
 * text is parsed, then every frame is added or, where the name exists, replaced, in one batch; any error in the
 * XML or against the frame model is reported with its line and column and nothing changes. The frames' scripts meet
 * the same syntax check as a frame saved through the API, so an import cannot bring in a script that would fail at
 * every firing.
 */
final class XmlTransfer implements Features.Xml {
    static final String SOURCE = "import";
    private final Features.Scripts scripts;

    XmlTransfer(Features.Scripts scripts) {
        this.scripts = requireNonNull(scripts, "scripts");
    }

    @Override public boolean available() {
        return true;
    }

    @Override public Reply exportXml(KnowledgeBase kb) {
        List<Frame> durable = kb.frames().stream().filter(f -> f.provenance().durable()).toList();
        StringWriter out = new StringWriter();
        KnowledgeXmlWriter.write(durable, out);
        return Reply.text(200, "application/xml; charset=utf-8", out.toString());
    }

    @Override public Object importXml(KnowledgeBase kb, JsonNode body) {
        String xml = FrameInput.text(body, "xml").orElseThrow(() ->
                new ApiException(400, "Importing needs the XML text in the field 'xml'."));
        List<SourcedFrame> frames;
        try {
            frames = KnowledgeLoader.parseTextToPut(xml, SOURCE, kb);
        } catch (KnowledgeXmlException e) {
            throw located(e.errors());
        }
        if (frames.isEmpty()) {
            throw ApiException.invalid(List.of(ApiProblem.of("", "", "The XML holds no FRAME element; nothing was imported.")));
        }
        List<Change> puts = new ArrayList<>(frames.size());
        frames.forEach(f -> puts.add(new Change.Put(f.frame())));
        List<ApiProblem> scriptProblems = scriptProblems(frames);
        if (!scriptProblems.isEmpty()) {
            List<ApiProblem> all = new ArrayList<>(scriptProblems);
            Map<String, SourceLocation> at = starts(frames);
            kb.problems(puts).forEach(p -> all.add(located(p, at)));
            throw rejected(all);
        }
        ChangeSet cs;
        try {
            cs = kb.apply(puts);
        } catch (BatchRejectedException e) {
            throw located(e, frames);
        }
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("version", cs.version());
        out.put("count", frames.size());
        out.put("changed", cs.events().size());
        out.put("frames", frames.stream().map(f -> f.frame().name()).toList());
        return out;
    }

    private static ApiException located(List<LoadError> errors) {
        List<ApiProblem> problems = errors.stream()
                .map(e -> new ApiProblem(e.frame().orElse(""), e.slot().orElse(""), e.message(), e.line(),
                        e.column())).toList();
        return new ApiException(422, problems.size() == 1 ? problems.getFirst().message()
                : problems.size() + " errors in the XML; nothing was imported.", problems);
    }

    /** One problem per script that does not parse, placed at the FRAME element of its frame. */
    private List<ApiProblem> scriptProblems(List<SourcedFrame> frames) {
        List<ApiProblem> problems = new ArrayList<>();
        for (SourcedFrame f : frames) {
            for (ApiProblem p : scripts.problems(f.frame())) {
                problems.add(new ApiProblem(p.frame(), p.slot(), p.message(), f.location().line(), f.location().column()));
            }
        }
        return problems;
    }

    /** Frame-model problems placed at the FRAME element of the frame they concern. */
    private static ApiException located(BatchRejectedException e, List<SourcedFrame> frames) {
        Map<String, SourceLocation> at = starts(frames);
        return rejected(e.problems().stream().map(p -> located(p, at)).toList());
    }

    private static ApiProblem located(Problem p, Map<String, SourceLocation> starts) {
        SourceLocation at = starts.get(p.frame());
        return new ApiProblem(p.frame(), p.slot().orElse(""), p.message(), at == null ? 0 : at.line(),
                at == null ? 0 : at.column());
    }

    /** Where each frame's FRAME element starts, by frame name. */
    private static Map<String, SourceLocation> starts(List<SourcedFrame> frames) {
        Map<String, SourceLocation> starts = HashMap.newHashMap(frames.size());
        frames.forEach(f -> starts.put(f.frame().name(), f.location()));
        return starts;
    }

    private static ApiException rejected(List<ApiProblem> problems) {
        return new ApiException(422, problems.size() == 1 ? problems.getFirst().message()
                : problems.size() + " problems; nothing was imported.", problems);
    }
}
