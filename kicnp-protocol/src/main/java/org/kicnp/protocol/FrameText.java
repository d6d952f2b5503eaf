package org.kicnp.protocol;

import static java.util.Objects.requireNonNull;

import java.util.List;
import java.util.function.IntFunction;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.xml.KnowledgeLoader;
import org.kicnp.core.xml.KnowledgeXmlWriter;
import org.kicnp.core.xml.SourcedFrame;

/**
 * Frames as they travel inside messages: the paper's XML text (section 3.2), read and written by the same loader
 * and writer as the knowledge files, so the wire and the files cannot disagree.
 */
public final class FrameText {
    private FrameText() {
    }

    /** The XML text of one frame. */
    public static String toXml(Frame frame) {
        return KnowledgeXmlWriter.toXml(requireNonNull(frame, "frame"));
    }

    /** The XML texts of several frames, in order. */
    public static List<String> toXml(List<Frame> frames) {
        return frames.stream().map(FrameText::toXml).toList();
    }

    /** One XML text (a KNOWLEDGEBASE document) holding several frames, in order. */
    public static String document(List<Frame> frames) {
        java.io.StringWriter w = new java.io.StringWriter();
        KnowledgeXmlWriter.write(requireNonNull(frames, "frames"), w);
        return w.toString();
    }

    /**
     * Parses the frames of one XML text, resolving slot types against {@code context}.
     *
     * @param source names the text in error messages, such as {@code "register from 'scout'"}
     * @throws org.kicnp.core.KnowledgeException listing every problem with its line and column
     */
    public static List<Frame> parse(String xml, String source, KnowledgeBase context) {
        return KnowledgeLoader.parseText(requireNonNull(xml, "xml"), source, context).stream()
                .map(SourcedFrame::frame).toList();
    }

    /**
     * Parses several XML texts as one set, as frames sent one per text (a push, the answer to a pull) must be: a
     * frame inherits declarations (a list slot's ARGUMENT) from the others whatever their order, then from
     * {@code context}, and a name given twice is an error.
     *
     * @param source names the text at each index in error messages, such as {@code "push from 'lab-a' #3"}
     * @throws org.kicnp.core.KnowledgeException listing every problem with its text, line and column
     */
    public static List<Frame> parse(List<String> xml, IntFunction<String> source, KnowledgeBase context) {
        return KnowledgeLoader.parseTexts(requireNonNull(xml, "xml"), source, context).stream()
                .map(SourcedFrame::frame).toList();
    }
}
