package org.kicnp.core.xml;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kicnp.core.KnowledgeBase;

class XmlSecurityTest {
    @TempDir Path dir;

    private KnowledgeXmlException loadFails(String xml) throws IOException {
        Path p = dir.resolve("hostile.xml");
        Files.writeString(p, xml);
        KnowledgeBase kb = KnowledgeBase.create();
        KnowledgeXmlException e = catchThrowableOfType(KnowledgeXmlException.class,
                () -> KnowledgeLoader.load(kb, List.of(p)));
        assertThat(e).as("loading a hostile file must fail").isNotNull();
        assertThat(kb.size()).isZero();
        return e;
    }

    @Test
    @Timeout(10)
    void load_whenDocumentHasDoctype_refusesItAtItsLocation() throws IOException {
        KnowledgeXmlException e = loadFails("""
                <?xml version="1.0"?>
                <!DOCTYPE FRAME [ <!ELEMENT FRAME ANY> ]>
                <FRAME><NAME>X</NAME></FRAME>
                """);

        assertThat(e.errors()).singleElement().satisfies(err -> {
            assertThat(err.line()).isEqualTo(2);
            assertThat(err.message()).startsWith("DTDs are not allowed");
        });
    }

    @Test
    @Timeout(10)
    void load_whenBillionLaughs_failsQuicklyWithoutExpanding() throws IOException {
        StringBuilder sb = new StringBuilder("<?xml version=\"1.0\"?>\n<!DOCTYPE lolz [\n<!ENTITY lol \"lol\">\n");
        for (int i = 1; i <= 9; i++) {
            String prev = i == 1 ? "lol" : "lol" + (i - 1);
            sb.append("<!ENTITY lol").append(i).append(" \"").append(("&" + prev + ";").repeat(10)).append("\">\n");
        }
        sb.append("]>\n<FRAME><NAME>&lol9;</NAME></FRAME>\n");
        long start = System.nanoTime();

        KnowledgeXmlException e = loadFails(sb.toString());

        assertThat(Duration.ofNanos(System.nanoTime() - start)).isLessThan(Duration.ofSeconds(5));
        assertThat(e.getMessage()).contains("DTDs are not allowed").doesNotContain("lollol");
    }

    @Test
    @Timeout(10)
    void load_whenExternalEntityPointsAtALocalFile_neverReadsIt() throws IOException {
        Path secret = dir.resolve("secret.txt");
        Files.writeString(secret, "TOP-SECRET-4711");
        String xml = "<?xml version=\"1.0\"?>\n<!DOCTYPE FRAME [ <!ENTITY xxe SYSTEM \"" + secret.toUri() + "\"> ]>\n"
                + "<FRAME><NAME>X</NAME><SLOTLIST><SLOT><NAME>s</NAME><TYPE>TYPE_STR</TYPE>"
                + "<VALUE>&xxe;</VALUE></SLOT></SLOTLIST></FRAME>\n";

        KnowledgeXmlException e = loadFails(xml);

        assertThat(e.getMessage()).contains("DTDs are not allowed").doesNotContain("TOP-SECRET");
        assertThat(e.errors()).allSatisfy(err -> assertThat(err.message()).doesNotContain("TOP-SECRET"));
    }

    @Test
    @Timeout(10)
    void parseText_whenEntityUndeclared_reportsItWithoutResolving() {
        String xml = "<FRAME><NAME>&xxe;</NAME></FRAME>";

        assertThatThrownBy(() -> KnowledgeLoader.parseText(xml, "net", KnowledgeBase.create()))
                .isInstanceOf(KnowledgeXmlException.class)
                .hasMessageStartingWith("net:1:")
                .hasMessageContaining("xxe");
    }

    @Test
    @Timeout(10)
    void parseText_whenNestedTooDeep_failsWithALimit() {
        String xml = "<FRAME><NAME>X</NAME><HASPART>" + "<PART>".repeat(100) + "</PART>".repeat(100)
                + "</HASPART></FRAME>";

        assertThatThrownBy(() -> KnowledgeLoader.parseText(xml, "net", KnowledgeBase.create()))
                .isInstanceOf(KnowledgeXmlException.class)
                .hasMessageContaining("net:1:");
    }

    @Test
    void load_whenFileLargerThanTheCap_refusesItBeforeReading() throws IOException {
        Path p = dir.resolve("big.xml");
        Files.writeString(p, "<KNOWLEDGEBASE>" + " ".repeat(2000) + "</KNOWLEDGEBASE>");
        String old = System.getProperty(SecureXml.MAX_BYTES_PROPERTY);
        System.setProperty(SecureXml.MAX_BYTES_PROPERTY, "1000");
        try {
            assertThatThrownBy(() -> KnowledgeLoader.load(KnowledgeBase.create(), List.of(p)))
                    .isInstanceOf(KnowledgeXmlException.class)
                    .hasMessage(p + ":1:1: The file is 2031 bytes, more than the limit of 1000 bytes (system property "
                            + "kicnp.xml.maxFileBytes).");
        } finally {
            if (old == null) {
                System.clearProperty(SecureXml.MAX_BYTES_PROPERTY);
            } else {
                System.setProperty(SecureXml.MAX_BYTES_PROPERTY, old);
            }
        }
    }
}
