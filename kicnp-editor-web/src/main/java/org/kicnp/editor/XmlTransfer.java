package org.kicnp.editor;

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
import org.kicnp.core.xml.SourcedFrame;

/**
 * Export and import in the paper's XML format (Table 4), through the core's reader and writer. Export writes the
 * durable frames (declared and learned; runtime frames are not knowledge to keep). Import is all or nothing: the
 * text is parsed, then every frame is added or, where the name exists, replaced, in one batch; any error in the
 * XML or against the frame model is reported with its line and column and nothing changes.
 */
final class XmlTransfer implements Features.Xml {
    static final String SOURCE = "import";

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

    /** Frame-model problems placed at the FRAME element of the frame they concern. */
    private static ApiException located(BatchRejectedException e, List<SourcedFrame> frames) {
        Map<String, SourcedFrame> byName = new HashMap<>();
        frames.forEach(f -> byName.put(f.frame().name(), f));
        List<ApiProblem> problems = new ArrayList<>();
        for (Problem p : e.problems()) {
            SourcedFrame at = byName.get(p.frame());
            problems.add(new ApiProblem(p.frame(), p.slot().orElse(""), p.message(),
                    at == null ? 0 : at.location().line(), at == null ? 0 : at.location().column()));
        }
        return new ApiException(422, problems.size() == 1 ? problems.getFirst().message()
                : problems.size() + " problems; nothing was imported.", problems);
    }
}
