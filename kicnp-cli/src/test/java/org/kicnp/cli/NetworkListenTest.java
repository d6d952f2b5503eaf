package org.kicnp.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.netty.handler.ssl.SslContext;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kicnp.cli.platform.Platform;
import org.kicnp.cli.platform.PlatformConfig;

/**
 * Agents on other machines: {@code serve --listen HOST:PORT} with TLS from a keystore made by the JDK's keytool, and
 * {@code kicnp agent --tls-trust} connecting to it, on the real platform and real sockets; the refusals of the
 * options, before anything starts.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class NetworkListenTest {
    @TempDir
    Path dir;

    private Path keytool(String... args) throws Exception {
        Path keytool = Path.of(System.getProperty("java.home"), "bin", "keytool");
        List<String> cmd = new java.util.ArrayList<>(List.of(keytool.toString()));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        String output = new String(p.getInputStream().readAllBytes());
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).as("keytool finished").isTrue();
        assertThat(p.exitValue()).as("keytool %s: %s", args[0], output).isZero();
        return dir;
    }

    /** A keystore with a self-signed key for 127.0.0.1, its password file, and the certificate as PEM. */
    private record Keys(Path keystore, Path password, Path certificate) {
    }

    private Keys keys() throws Exception {
        Path store = dir.resolve("gateway.p12");
        Path password = Files.writeString(dir.resolve("keystore-password"), "s3cret-pass\n");
        Path pem = dir.resolve("gateway.pem");
        keytool("-genkeypair", "-alias", "kicnp", "-keyalg", "EC", "-groupname", "secp256r1", "-dname",
                "CN=localhost", "-ext", "san=ip:127.0.0.1", "-validity", "2", "-storetype", "PKCS12", "-keystore",
                store.toString(), "-storepass", "s3cret-pass", "-keypass", "s3cret-pass");
        keytool("-exportcert", "-rfc", "-alias", "kicnp", "-keystore", store.toString(), "-storepass", "s3cret-pass",
                "-file", pem.toString());
        return new Keys(store, password, pem);
    }

    private Path knowledge() throws Exception {
        Path kb = Files.createDirectories(dir.resolve("kb"));
        Files.writeString(kb.resolve("cups.xml"), """
                <KNOWLEDGEBASE>
                  <FRAME><NAME>Cup</NAME></FRAME>
                  <FRAME><NAME>cup1</NAME><ISA>Cup</ISA><ISINSTANCE>TRUE</ISINSTANCE></FRAME>
                </KNOWLEDGEBASE>
                """);
        return kb;
    }

    @Test
    void agentOnTheListenAddress_queriesOverTls_andWithoutTrustCannot_whileLoopbackStaysPlain() throws Exception {
        Keys keys = keys();
        SslContext tls = TlsFiles.server(keys.keystore(), keys.password());
        PlatformConfig config = PlatformConfig.of(knowledge()).withEphemeralPorts().withHttpPort(Optional.empty())
                .withAgentListener(Optional.of(new PlatformConfig.AgentListener("127.0.0.1", 0, Optional.of(tls))));

        try (Platform platform = Platform.start(config)) {
            int listen = platform.agentListenerAddress().orElseThrow().getPort();
            assertThat(listen).isNotEqualTo(platform.gatewayPort());
            String tokens = platform.agentsFile().toString();

            CliRun overTls = CliRun.of("agent", "--gateway", "127.0.0.1:" + listen, "--tokens", tokens,
                    "--tls-trust", keys.certificate().toString(), "query", "Cup");
            assertThat(overTls.exitCode()).as(overTls.err()).isZero();
            assertThat(overTls.out()).contains("<NAME>cup1</NAME>");

            CliRun trustingTheKeystore = CliRun.of("agent", "--gateway", "127.0.0.1:" + listen, "--tokens", tokens,
                    "--tls-trust", keys.keystore().toString(), "--tls-password-file", keys.password().toString(),
                    "query", "Cup");
            assertThat(trustingTheKeystore.exitCode()).as(trustingTheKeystore.err()).isZero();
            assertThat(trustingTheKeystore.out()).contains("<NAME>cup1</NAME>");

            CliRun plainToTls = CliRun.of("agent", "--gateway", "127.0.0.1:" + listen, "--tokens", tokens,
                    "--timeout", "2", "query", "Cup");
            assertThat(plainToTls.exitCode()).isEqualTo(1);
            assertThat(plainToTls.out()).doesNotContain("cup1");

            CliRun loopback = CliRun.of("agent", "--gateway", "127.0.0.1:" + platform.gatewayPort(), "--tokens",
                    tokens, "query", "Cup");
            assertThat(loopback.exitCode()).as(loopback.err()).isZero();
            assertThat(loopback.out()).contains("<NAME>cup1</NAME>");
        }
    }

    @Test
    void agentTrustingAnotherCertificate_isRefusedTheConnection() throws Exception {
        Keys keys = keys();
        Path other = dir.resolve("other.p12");
        Path otherPem = dir.resolve("other.pem");
        keytool("-genkeypair", "-alias", "other", "-keyalg", "EC", "-groupname", "secp256r1", "-dname", "CN=other",
                "-ext", "san=ip:127.0.0.1", "-validity", "2", "-storetype", "PKCS12", "-keystore", other.toString(),
                "-storepass", "other-pass", "-keypass", "other-pass");
        keytool("-exportcert", "-rfc", "-alias", "other", "-keystore", other.toString(), "-storepass", "other-pass",
                "-file", otherPem.toString());
        PlatformConfig config = PlatformConfig.of(knowledge()).withEphemeralPorts().withHttpPort(Optional.empty())
                .withAgentListener(Optional.of(new PlatformConfig.AgentListener("127.0.0.1", 0,
                        Optional.of(TlsFiles.server(keys.keystore(), keys.password())))));

        try (Platform platform = Platform.start(config)) {
            int listen = platform.agentListenerAddress().orElseThrow().getPort();
            CliRun r = CliRun.of("agent", "--gateway", "127.0.0.1:" + listen, "--tokens",
                    platform.agentsFile().toString(), "--timeout", "2", "--tls-trust", otherPem.toString(),
                    "query", "Cup");
            assertThat(r.exitCode()).isEqualTo(1);
            assertThat(r.out()).doesNotContain("cup1");
        }
    }

    @Test
    void serveListen_withoutTls_isRefused_namingWhatToGive() throws Exception {
        CliRun r = CliRun.of("serve", knowledge().toString(), "--gateway-port", "0", "--http-port", "0",
                "--listen", "0.0.0.0:0");

        assertThat(r.exitCode()).isEqualTo(2);
        assertThat(r.err()).contains("--listen 0.0.0.0:0 lets other machines connect, so it needs TLS",
                "--tls-keystore FILE", "--tls-password-file FILE", "--plaintext-listen");
    }

    @Test
    void serveTlsOptions_withoutListen_orBoth_orABadAddress_areUsageErrors() throws Exception {
        String kb = knowledge().toString();
        Keys keys = keys();

        CliRun noListen = CliRun.of("serve", kb, "--tls-keystore", keys.keystore().toString());
        assertThat(noListen.exitCode()).isEqualTo(2);
        assertThat(noListen.err()).contains("are options of --listen HOST:PORT, which was not given");

        CliRun both = CliRun.of("serve", kb, "--listen", "127.0.0.1:0", "--plaintext-listen", "--tls-keystore",
                keys.keystore().toString(), "--tls-password-file", keys.password().toString());
        assertThat(both.exitCode()).isEqualTo(2);
        assertThat(both.err()).contains("--plaintext-listen and --tls-keystore exclude each other");

        CliRun badAddress = CliRun.of("serve", kb, "--listen", "nowhere");
        assertThat(badAddress.exitCode()).isEqualTo(2);
        assertThat(badAddress.err()).contains("--listen 'nowhere' is not HOST:PORT");
    }

    @Test
    void serveKeystoreProblems_nameTheFile() throws Exception {
        String kb = knowledge().toString();
        Keys keys = keys();
        Path wrong = Files.writeString(dir.resolve("wrong-password"), "not-it\n");
        Path missing = dir.resolve("missing.p12");

        CliRun wrongPassword = CliRun.of("serve", kb, "--listen", "127.0.0.1:0", "--tls-keystore",
                keys.keystore().toString(), "--tls-password-file", wrong.toString());
        assertThat(wrongPassword.exitCode()).isEqualTo(2);
        assertThat(wrongPassword.err()).contains("The keystore '" + keys.keystore() + "' (--tls-keystore) cannot be "
                + "opened");

        CliRun noFile = CliRun.of("serve", kb, "--listen", "127.0.0.1:0", "--tls-keystore", missing.toString(),
                "--tls-password-file", keys.password().toString());
        assertThat(noFile.exitCode()).isEqualTo(2);
        assertThat(noFile.err()).contains("There is no keystore '" + missing + "' (--tls-keystore).");

        CliRun certificateOnly = CliRun.of("serve", kb, "--listen", "127.0.0.1:0", "--tls-keystore",
                keys.certificate().toString(), "--tls-password-file", keys.password().toString());
        assertThat(certificateOnly.exitCode()).isEqualTo(2);
        assertThat(certificateOnly.err()).contains("'" + keys.certificate() + "' (--tls-keystore)");
    }

    @Test
    void agentTrustProblems_nameTheFile_beforeConnecting() throws Exception {
        Path tokens = Files.writeString(dir.resolve("agents.properties"), "director.token = x\n");
        Path missing = dir.resolve("missing.pem");
        Path notACertificate = Files.writeString(dir.resolve("junk.pem"), "hello\n");

        CliRun noFile = CliRun.of("agent", "--gateway", "127.0.0.1:1", "--tokens", tokens.toString(), "--tls-trust",
                missing.toString(), "query", "Cup");
        assertThat(noFile.exitCode()).isEqualTo(2);
        assertThat(noFile.err()).contains("'" + missing + "' (--tls-trust) cannot be read");

        CliRun junk = CliRun.of("agent", "--gateway", "127.0.0.1:1", "--tokens", tokens.toString(), "--tls-trust",
                notACertificate.toString(), "query", "Cup");
        assertThat(junk.exitCode()).isEqualTo(2);
        assertThat(junk.err()).contains("'" + notACertificate + "' (--tls-trust)");

        CliRun passwordAlone = CliRun.of("agent", "--gateway", "127.0.0.1:1", "--tokens", tokens.toString(),
                "--tls-password-file", tokens.toString(), "query", "Cup");
        assertThat(passwordAlone.exitCode()).isEqualTo(2);
        assertThat(passwordAlone.err()).contains("--tls-password-file is the password of --tls-trust");
    }

    @Test
    void tlsFilesServer_refusesAKeystoreWithoutAPrivateKey() throws Exception {
        Keys keys = keys();
        Path trustOnly = dir.resolve("trust.p12");
        keytool("-importcert", "-noprompt", "-alias", "gw", "-file", keys.certificate().toString(), "-storetype",
                "PKCS12", "-keystore", trustOnly.toString(), "-storepass", "s3cret-pass");

        assertThatThrownBy(() -> TlsFiles.server(trustOnly, keys.password()))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("'" + trustOnly + "' (--tls-keystore) holds no private key");
    }
}
