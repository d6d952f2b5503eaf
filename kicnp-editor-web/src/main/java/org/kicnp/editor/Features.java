package org.kicnp.editor;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.List;
import java.util.Set;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;

/**
 * The parts of the API that lean on other components: XML import/export (the paper's format), the script
 * syntax check and the view of a running inference engine. Each is a seam so the editor runs without the
 * component (the inference engine is optional per server); an absent feature answers 501 with a sentence
 * saying so, and {@code GET /api/session} tells the page.
 */
record Features(Xml xml, Scripts scripts, Inference inference) {

    /** XML export and all-or-nothing import. */
    interface Xml {
        boolean available();

        Reply exportXml(KnowledgeBase kb);

        /** Imports the XML text in {@code body.xml}; answers what was imported. */
        Object importXml(KnowledgeBase kb, JsonNode body);
    }

    /** Syntax check of a script before it is saved. */
    interface Scripts {
        boolean available();

        /** Checks {@code body.source}; answers {@code {ok, message, line, column}}. */
        Object check(JsonNode body);

        /**
         * One problem, naming frame and slot, per script of {@code frame} that does not parse (script slots, demons,
         * {@code js:} conditions): a frame saved through the API meets the check the page makes before saving.
         */
        List<ApiProblem> problems(Frame frame);
    }

    /** The live view of an inference engine: working memory, agenda, explanations, questions, runs. */
    interface Inference extends AutoCloseable {
        boolean available();

        /** Starts forwarding trace events to the page. */
        void attach(EventHub events);

        Object status();

        Object why(String instance);

        Object ask(String className);

        /** Backward chaining's proof trees for the class: why each answer holds, without side effects. */
        Object prove(String className);

        /** Why a behavior frame has not fired: its slots' candidates and each binding's outcome; no side effects. */
        Object whyNot(String frame);

        Object run();

        /**
         * Destroys an instance through the engine: it and every instance derived from it, in one batch (truth
         * maintenance); returns the names removed.
         */
        Set<String> destroy(String instance);

        @Override void close();
    }

    static Inference noInference() {
        return new Inference() {
            @Override public boolean available() {
                return false;
            }

            @Override public void attach(EventHub events) {
            }

            @Override public Object status() {
                throw unavailable();
            }

            @Override public Object why(String instance) {
                throw unavailable();
            }

            @Override public Object ask(String className) {
                throw unavailable();
            }

            @Override public Object prove(String className) {
                throw unavailable();
            }

            @Override public Object whyNot(String frame) {
                throw unavailable();
            }

            @Override public Object run() {
                throw unavailable();
            }

            @Override public Set<String> destroy(String instance) {
                throw unavailable();
            }

            @Override public void close() {
            }

            private ApiException unavailable() {
                return new ApiException(501, "No inference engine is attached to this editor.");
            }
        };
    }

    Features withInference(Inference i) {
        return new Features(xml, scripts, i);
    }

    static Xml noXml() {
        return new Xml() {
            @Override public boolean available() {
                return false;
            }

            @Override public Reply exportXml(KnowledgeBase kb) {
                throw new ApiException(501, "XML export is not available in this build of the editor.");
            }

            @Override public Object importXml(KnowledgeBase kb, JsonNode body) {
                throw new ApiException(501, "XML import is not available in this build of the editor.");
            }
        };
    }

    static Scripts noScripts() {
        return new Scripts() {
            @Override public boolean available() {
                return false;
            }

            @Override public Object check(JsonNode body) {
                throw new ApiException(501, "The script check is not available in this build of the editor.");
            }

            @Override public List<ApiProblem> problems(Frame frame) {
                return List.of(); // no runtime to parse with: the scripts are checked when they first run
            }
        };
    }
}
