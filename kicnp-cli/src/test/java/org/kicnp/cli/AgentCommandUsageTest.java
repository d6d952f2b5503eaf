package org.kicnp.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * {@code kicnp agent} against a real gateway on loopback: its options, the gateway's address and the agent file.
 * Malformed options and arguments, addresses and agents missing from the file are usage errors (exit 2, naming what
 * is wrong); a token the server refuses, or no server there, exits 1 saying so.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class AgentCommandUsageTest extends AgentCommandFixture {
    @Test
    void malformedOptionsAndArguments_areUsageErrors_exit2_namingWhatIsWrong() {
        record Case(List<String> args, String says) { }
        List<Case> cases = List.of(
                new Case(List.of("--timeout", "NaN", "query", "Person"),
                        "--timeout must be a number of seconds above 0, not NaN."),
                new Case(List.of("--timeout", "0", "query", "Person"),
                        "--timeout must be a number of seconds above 0, not 0.0."),
                new Case(List.of("watch", "Person", "--for", "NaN"),
                        "--for must be a number of seconds above 0, not NaN."),
                new Case(List.of("command", "scout", "walk", "--wait", "0"),
                        "--wait must be a number of seconds above 0, not 0.0."),
                new Case(List.of("command", "scout", "walk", "--wait=-5"),
                        "--wait must be a number of seconds above 0, not -5.0."),
                new Case(List.of("command", "", "walk"),
                        "ROBOT '' is not an agent name: use letters, digits, '_' and '-', starting with a letter or '_'."),
                new Case(List.of("command", "scout", " "), "ACTION is empty; name the action to send to 'scout'."),
                new Case(List.of("cancel", "my robot", "director-1"), "ROBOT 'my robot' is not an agent name"),
                new Case(List.of("sensor", "sonar", "1", "--ttl", "0"), "--ttl must be 1 to 86400000 milliseconds, not 0."),
                new Case(List.of("sensor", "sonar", "1", "--rate", "0"),
                        "--rate must be above 0 and at most 1000 a second, not 0.0."),
                new Case(List.of("sensor", "sonar", "1", "--for", "-1"),
                        "--for must be a number of seconds above 0, not -1.0."),
                new Case(List.of("sensor", "sonar", "[1, 2", "--for", "1"),
                        "VALUE '[1, 2' starts a list but is not a JSON array"),
                new Case(List.of("sensor", "sonar", "[null]", "--for", "1"),
                        "VALUE '[null]' holds null, which is no slot value"),
                new Case(List.of("sensor", "no spaces", "1", "--for", "1"),
                        "SENSOR 'no spaces' is not a sensor name: use letters, digits, '_' and '-'"));
        for (Case c : cases) {
            CliRun r = agent(c.args().toArray(String[]::new));
            assertThat(r.exitCode()).as(c.args() + ": " + r.err()).isEqualTo(2);
            assertThat(r.err()).as(c.args().toString()).contains(c.says()).doesNotContain("Exception");
        }

        for (String gateway : List.of("localhost:99999", "localhost:", "localhost", ":" + server.port())) {
            CliRun r = CliRun.of("agent", "--gateway", gateway, "--tokens", tokens.toString(), "query", "Person");
            assertThat(r.exitCode()).as(gateway + ": " + r.err()).isEqualTo(2);
            assertThat(r.err()).contains("--gateway '" + gateway + "' is not HOST:PORT with a port from 1 to 65535.")
                    .doesNotContain("Exception");
        }
    }

    @Test
    void gateway_mayBeAnIpv6AddressInBrackets() {
        CliRun r = CliRun.of("agent", "--gateway", "[::1]:1", "--tokens", tokens.toString(), "--timeout", "0.5",
                "query", "Person");

        // Not a usage error: the address is read, and nothing listens there.
        assertThat(r.exitCode()).as(r.err()).isEqualTo(1);
        assertThat(r.err()).contains("was not registered with ::1:1");
    }

    @Test
    void aWrongToken_isRefusedByTheServer_exit1() {
        CliRun r = agent("--as", "intruder", "query", "Person");

        assertThat(r.exitCode()).isEqualTo(1);
        assertThat(r.err()).contains("kicnp agent query: Server refused agent 'intruder': Unknown agent 'intruder' or "
                + "wrong token.\n");
        assertThat(server.registeredAgents()).doesNotContain("intruder");
    }

    @Test
    void anAgentMissingFromTheFile_orNoFile_isAUsageError() {
        CliRun missing = agent("--as", "nobody", "query", "Person");
        assertThat(missing.exitCode()).isEqualTo(2);
        assertThat(missing.err()).contains("has no 'nobody.token'.");

        CliRun noFile = CliRun.of("agent", "--tokens", dir.resolve("none.properties").toString(), "query", "Person");
        assertThat(noFile.exitCode()).isEqualTo(2);
        assertThat(noFile.err()).contains("There is no agent file").contains("none.properties");
    }

    @Test
    void noServerThere_exits1SayingSoWithinTheTimeout() throws Exception {
        int port = server.port();
        server.close();

        CliRun r = CliRun.of("agent", "--gateway", "127.0.0.1:" + port, "--tokens", tokens.toString(),
                "--timeout", "1", "query", "Person");

        assertThat(r.exitCode()).isEqualTo(1);
        assertThat(r.err()).contains("was not registered with 127.0.0.1:" + port);
    }
}
