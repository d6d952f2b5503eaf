package org.kicnp.core.xml;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.kicnp.core.KnowledgeBase;

/** Knowledge files for the loader's error tests: written to a test's directory, loaded, their errors as printed. */
final class LoaderErrorFiles {
    private LoaderErrorFiles() {
    }

    static Path write(Path dir, String name, String xml) throws IOException {
        Path p = dir.resolve(name);
        Files.writeString(p, xml);
        return p;
    }

    /** The errors of loading {@code paths} into a new knowledge base, formatted; the load must fail. */
    static List<String> errors(List<Path> paths) {
        KnowledgeXmlException e = catchThrowableOfType(KnowledgeXmlException.class,
                () -> KnowledgeLoader.load(KnowledgeBase.create(), paths));
        assertThat(e).as("load should fail").isNotNull();
        return e.errors().stream().map(LoadError::format).toList();
    }

    static String classFrame(String name, String parent) {
        return "  <FRAME>\n    <NAME>" + name + "</NAME>\n" + (parent == null ? "" : "    <ISA>" + parent + "</ISA>\n")
                + "    <ISINSTANCE>FALSE</ISINSTANCE>\n  </FRAME>\n";
    }

    static String kb(String... frames) {
        return "<KNOWLEDGEBASE>\n" + String.join("", frames) + "</KNOWLEDGEBASE>\n";
    }
}
