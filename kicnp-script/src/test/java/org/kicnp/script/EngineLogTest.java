package org.kicnp.script;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.logging.Level;
import java.util.logging.LogRecord;

import org.junit.jupiter.api.Test;

class EngineLogTest {
    @Test
    void anEngineWarning_isLoggedAsTheEngines_withItsParameters_notAsAScriptsErrorOutput() {
        LogRecord record = new LogRecord(Level.WARNING, "Option {0} is ignored here.");
        record.setLoggerName("engine");
        record.setParameters(new Object[] {"engine.Mode"});

        String log = stderrOf(() -> new EngineLog().publish(record));

        assertThat(log).contains("WARN org.kicnp.script.engine - [engine] Option engine.Mode is ignored here.")
                .doesNotContain("Script error output");
    }

    @Test
    void aFineEngineMessage_staysOutOfTheDefaultLog() {
        LogRecord record = new LogRecord(Level.FINE, "compiled something");
        record.setLoggerName("engine");

        assertThat(stderrOf(() -> new EngineLog().publish(record))).doesNotContain("compiled something");
    }

    /** What slf4j-simple (which writes to the standard error stream of the moment) printed while {@code body} ran. */
    private static String stderrOf(Runnable body) {
        PrintStream old = System.err;
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
        try {
            body.run();
        } finally {
            System.setErr(old);
        }
        return err.toString(StandardCharsets.UTF_8);
    }
}
