package org.kicnp.cli;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.io.TempDir;
import org.kicnp.core.Change;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.kicnp.gateway.AgentDirectory;
import org.kicnp.gateway.FeedbackListener;
import org.kicnp.gateway.GatewayConfig;
import org.kicnp.gateway.GatewayServer;
import org.kicnp.protocol.AgentKind;

/**
 * What the {@code kicnp agent} tests share: a real gateway on loopback holding a 'Person' class and its instance
 * 'ken', the agents it knows ('director', 'listener', 'scout'), an agent file for the command line, and the command
 * run against that gateway with that file.
 */
abstract class AgentCommandFixture {
    static final ObjectMapper JSON = new ObjectMapper();
    @TempDir Path dir;
    KnowledgeBase kb;
    GatewayServer server;
    Path tokens;

    @BeforeEach
    void start() throws Exception {
        kb = KnowledgeBase.create();
        kb.apply(List.of(
                new Change.Add(Frame.classFrame("Person").slot(Slot.builder("name", DataType.STRING).build()).build()),
                new Change.Add(Frame.instance("ken", "Person")
                        .slot(Slot.ofValue("name", DataType.STRING, Value.of("Ken"))).build())));
        AgentDirectory agents = AgentDirectory.empty()
                .with("director", "director-secret", AgentKind.USER)
                .with("listener", "listener-secret", AgentKind.USER)
                .with("scout", "scout-secret", AgentKind.ROBOT);
        tokens = Files.write(dir.resolve("agents.properties"), List.of(
                "director.token = director-secret", "director.kinds = user",
                "intruder.token = wrong-secret"));
        server = GatewayServer.start(GatewayConfig.defaults().withPort(0), agents, kb, FeedbackListener.NONE);
    }

    @AfterEach
    void stop() {
        server.close();
    }

    CliRun agent(String... args) {
        String[] all = new String[args.length + 5];
        all[0] = "agent";
        all[1] = "--gateway";
        all[2] = "127.0.0.1:" + server.port();
        all[3] = "--tokens";
        all[4] = tokens.toString();
        System.arraycopy(args, 0, all, 5, args.length);
        return CliRun.of(all);
    }
}
