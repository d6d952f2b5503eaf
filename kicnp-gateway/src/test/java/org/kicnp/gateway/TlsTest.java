package org.kicnp.gateway;

import static org.assertj.core.api.Assertions.assertThat;

import io.netty.handler.ssl.SslContext;
import io.netty.handler.ssl.SslContextBuilder;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.KeyStore;
import java.time.Duration;
import java.util.concurrent.TimeUnit;
import javax.net.ssl.KeyManagerFactory;
import javax.net.ssl.SSLContext;
import javax.net.ssl.TrustManagerFactory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kicnp.agent.AgentOptions;
import org.kicnp.agent.UserAgent;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.protocol.AgentKind;

/** The gateway over TLS with a self-signed certificate made by the JDK's keytool; the SDK trusts exactly it. */
class TlsTest {
    private static final char[] PASSWORD = "changeit".toCharArray();

    @Test
    void agent_connectsAndQueries_overTls(@TempDir Path dir) throws Exception {
        KeyStore store = selfSigned(dir.resolve("gateway.p12"));
        KeyManagerFactory kmf = KeyManagerFactory.getInstance(KeyManagerFactory.getDefaultAlgorithm());
        kmf.init(store, PASSWORD);
        SslContext serverTls = SslContextBuilder.forServer(kmf).build();
        TrustManagerFactory tmf = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm());
        tmf.init(store);
        SSLContext clientTls = SSLContext.getInstance("TLS");
        clientTls.init(null, tmf.getTrustManagers(), null);

        KnowledgeBase kb = KnowledgeBase.create();
        kb.add(Frame.classFrame("Cup").build());
        kb.add(Frame.instance("cup1", "Cup").build());
        try (GatewayServer server = GatewayServer.start(GatewayConfig.defaults().withPort(0).withTls(serverTls),
                GatewayEndToEndTest.AGENTS, kb, FeedbackListener.NONE);
             UserAgent alice = new UserAgent(AgentOptions.of("127.0.0.1", server.port(), "alice", AgentKind.USER,
                     "alice-token").withSocketFactory(clientTls.getSocketFactory()))) {
            alice.startAndAwait(Duration.ofSeconds(15));
            assertThat(alice.query("Cup")).extracting(Frame::name).containsExactly("cup1");

            try (RawClient plain = new RawClient(server.port())) { // a plaintext client cannot talk to it
                plain.send(new org.kicnp.protocol.Message.Query("1", "Cup"));
                assertThat(plain.readUntilClosed()).isEmpty();
            }
        }
    }

    private static KeyStore selfSigned(Path file) throws Exception {
        Path keytool = Path.of(System.getProperty("java.home"), "bin", "keytool");
        Process p = new ProcessBuilder(keytool.toString(), "-genkeypair", "-alias", "kicnp", "-keyalg", "EC",
                "-groupname", "secp256r1", "-dname", "CN=localhost", "-ext", "san=ip:127.0.0.1", "-validity", "2",
                "-storetype", "PKCS12", "-keystore", file.toString(), "-storepass", "changeit", "-keypass", "changeit")
                .redirectErrorStream(true).start();
        String output = new String(p.getInputStream().readAllBytes());
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).as("keytool finished").isTrue();
        assertThat(p.exitValue()).as("keytool: %s", output).isZero();
        KeyStore ks = KeyStore.getInstance("PKCS12");
        try (InputStream in = Files.newInputStream(file)) {
            ks.load(in, PASSWORD);
        }
        return ks;
    }
}
