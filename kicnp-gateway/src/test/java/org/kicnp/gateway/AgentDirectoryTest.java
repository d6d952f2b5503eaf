package org.kicnp.gateway;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Properties;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Message.Hello;

class AgentDirectoryTest {
    @Test
    void load_readsTokensAndKinds(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("agents.properties");
        Files.writeString(file, "# who may connect\nscout.token = s3cret\nscout.kinds = robot\nalice.token = pw\n");
        AgentDirectory d = AgentDirectory.load(file);
        assertThat(d.refusal(new Hello("1", "scout", AgentKind.ROBOT, "s3cret"))).isEmpty();
        assertThat(d.refusal(new Hello("1", "scout", AgentKind.USER, "s3cret")))
                .contains("Agent 'scout' may not connect as a user agent.");
        assertThat(d.refusal(new Hello("1", "alice", AgentKind.PEER, "pw"))).isEmpty();
        assertThat(d.refusal(new Hello("1", "alice", AgentKind.USER, "PW"))).contains("Unknown agent 'alice' or wrong token.");
        assertThat(d.refusal(new Hello("1", "eve", AgentKind.USER, "pw"))).contains("Unknown agent 'eve' or wrong token.");
    }

    /**
     * A hello under an unknown name costs what one under a known name does, so timing does not tell which names
     * exist: with a 16 MB token the work is the token's hashing in both cases, where skipping the comparison for an
     * unknown name answered thousands of times faster. The margin (a tenth) leaves room for a loaded machine.
     */
    @Test
    void refusal_ofAnUnknownName_takesTheWorkOfAWrongToken() {
        AgentDirectory d = AgentDirectory.empty().with("alice", "pw");
        String token = "x".repeat(16 << 20);
        Hello known = new Hello("1", "alice", AgentKind.USER, token);
        Hello unknown = new Hello("1", "eve", AgentKind.USER, token);
        long knownNanos = fastest(() -> d.refusal(known));
        long unknownNanos = fastest(() -> d.refusal(unknown));
        assertThat(unknownNanos).as("nanoseconds for an unknown name, against %d for a wrong token", knownNanos)
                .isGreaterThan(knownNanos / 10);
    }

    private static long fastest(Runnable r) {
        long best = Long.MAX_VALUE;
        for (int i = 0; i < 5; i++) {
            long start = System.nanoTime();
            r.run();
            best = Math.min(best, System.nanoTime() - start);
        }
        return best;
    }

    @Test
    void of_whenKindUnknown_namesKeyAndSource() throws Exception {
        Properties p = new Properties();
        p.load(new StringReader("scout.token=t\nscout.kinds=robot,toaster\n"));
        assertThatThrownBy(() -> AgentDirectory.of(p, "agents.properties")).isInstanceOf(GatewayException.class)
                .hasMessage("Unknown agent kind 'toaster' for 'scout.kinds' in 'agents.properties'; use robot, user, "
                        + "service or peer.");
    }

    @Test
    void of_whenKeyIsNeitherTokenNorKinds_refusesIt() throws Exception {
        Properties p = new Properties();
        p.load(new StringReader("scout.password=t\n"));
        assertThatThrownBy(() -> AgentDirectory.of(p, "a.properties"))
                .hasMessage("Key 'scout.password' in the agent file 'a.properties' is neither NAME.token nor NAME.kinds.");
    }

    @Test
    void of_whenKindsWithoutToken_refusesIt() throws Exception {
        Properties p = new Properties();
        p.load(new StringReader("scout.kinds=robot\n"));
        assertThatThrownBy(() -> AgentDirectory.of(p, "a.properties"))
                .hasMessage("Agent 'scout' in 'a.properties' has kinds but no token.");
    }

    /** A blank token (a placeholder left in the file) would admit anyone who sends the empty token under that name. */
    @Test
    void of_whenATokenIsBlank_refusesIt() throws Exception {
        Properties p = new Properties();
        p.load(new StringReader("scout.token =   \nscout.kinds = robot\n"));
        assertThatThrownBy(() -> AgentDirectory.of(p, "a.properties")).isInstanceOf(GatewayException.class)
                .hasMessage("Agent 'scout' in 'a.properties' has an empty token; give it a secret, or remove it.");
        assertThatThrownBy(() -> AgentDirectory.empty().with("scout", "")).isInstanceOf(GatewayException.class)
                .hasMessage("Agent 'scout' has an empty token; give it a secret.");
    }
}
