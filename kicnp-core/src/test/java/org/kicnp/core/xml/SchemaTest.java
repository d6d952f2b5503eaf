package org.kicnp.core.xml;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import javax.xml.XMLConstants;
import javax.xml.transform.stream.StreamSource;
import javax.xml.validation.Schema;
import javax.xml.validation.SchemaFactory;
import javax.xml.validation.Validator;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.kicnp.core.KnowledgeBase;
import org.xml.sax.SAXException;

/** The XSD in docs/ describes what the loader reads and the writer writes. */
class SchemaTest {
    private static Schema schema;

    @BeforeAll
    static void compileSchema() throws SAXException {
        SchemaFactory f = SchemaFactory.newInstance(XMLConstants.W3C_XML_SCHEMA_NS_URI);
        f.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
        f.setProperty(XMLConstants.ACCESS_EXTERNAL_DTD, "");
        f.setProperty(XMLConstants.ACCESS_EXTERNAL_SCHEMA, "");
        schema = f.newSchema(Path.of("..", "docs", "kicnp-kb.xsd").toFile());
    }

    private static void validate(StreamSource source) throws SAXException, IOException {
        Validator v = schema.newValidator();
        v.setProperty(XMLConstants.ACCESS_EXTERNAL_DTD, "");
        v.setProperty(XMLConstants.ACCESS_EXTERNAL_SCHEMA, "");
        v.validate(source);
    }

    static Stream<Path> scenarioFiles() {
        return KnowledgeLoader.expand(List.of(Path.of("..", "scenarios"))).stream();
    }

    @ParameterizedTest
    @MethodSource("scenarioFiles")
    void scenarioFile_isValidAgainstTheSchema(Path file) throws Exception {
        validate(new StreamSource(file.toFile()));
    }

    @Test
    void writerOutput_isValidAgainstTheSchema() throws Exception {
        KnowledgeBase kb = KnowledgeBase.create();
        KnowledgeLoader.load(kb, List.of(ScenarioFilesTest.TABLE5));
        java.io.StringWriter out = new java.io.StringWriter();
        KnowledgeXmlWriter.write(kb.frames(), out);
        java.io.StringWriter all = new java.io.StringWriter();
        KnowledgeXmlWriter.write(KnowledgeXmlWriterTest.everything(), all);

        validate(new StreamSource(new StringReader(out.toString())));
        validate(new StreamSource(new StringReader(all.toString())));
        validate(new StreamSource(new StringReader(KnowledgeXmlWriter.toXml(kb.require("Greeting")))));
    }

    @Test
    void schema_rejectsAnUnknownElement() {
        String xml = "<FRAME><NAME>X</NAME><COLOUR>red</COLOUR></FRAME>";

        assertThatThrownBy(() -> validate(new StreamSource(new StringReader(xml))))
                .isInstanceOf(SAXException.class)
                .hasMessageContaining("COLOUR");
    }

    @Test
    void scenarioDirectory_holdsTheTable5Files() throws IOException {
        try (Stream<Path> files = Files.list(ScenarioFilesTest.TABLE5)) {
            assertThat(files.map(p -> p.getFileName().toString()))
                    .contains("hierarchy.xml", "ask-user-name.xml", "greeting.xml", "section44.xml");
        }
    }
}
