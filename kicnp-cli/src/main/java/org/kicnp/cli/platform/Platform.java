package org.kicnp.cli.platform;

import java.net.InetSocketAddress;
import java.nio.file.Path;
import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.store.KnowledgeStore;
import org.kicnp.editor.EditorConfig;
import org.kicnp.editor.ChatPort;
import org.kicnp.editor.EditorServer;
import org.kicnp.editor.PlatformPorts;
import org.kicnp.editor.TeleOperation;
import org.kicnp.gateway.AgentDirectory;
import org.kicnp.gateway.GatewayConfig;
import org.kicnp.gateway.GatewayServer;
import org.kicnp.gateway.Transport;
import org.kicnp.inference.GraalScriptHost;
import org.kicnp.inference.InferenceEngine;
import org.kicnp.script.ScriptConfig;
import org.kicnp.script.ScriptRuntime;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The platform in one process (the paper's Figure 2): the knowledge base opened durably from its directory, the
 * inference engine running by itself on one thread, the network gateway the agents connect to, and the knowledge
 * editor. The engine's actions go to the gateway, the robots' feedback back to the engine; sensor signals become
 * RUNTIME instances in the knowledge base (the gateway does this), so slot conditions can wait on them. Everything
 * that happens is written to the {@link EventLog}. {@link #close} stops it all, the store last (it compacts).
 */
public final class Platform implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(Platform.class);
    private static final DateTimeFormatter STAMP = DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss-SSS").withZone(ZoneOffset.UTC);

    /**
     * Time a behavior frame's script may run. Longer than the script runtime's default: the first runs of a script
     * are interpreted (and slow on a loaded machine) until the JIT has compiled it.
     */
    static final java.time.Duration SCRIPT_TIME_LIMIT = java.time.Duration.ofSeconds(5);

    private final KnowledgeStore store;
    private final ScriptRuntime scripts;
    private final EventLog log;
    private final ExecutorService engineThread;
    private final ScheduledExecutorService ticker;
    private final InferenceEngine engine;
    private final GatewayServer gateway;
    private final Optional<EditorServer> editor;
    private final Path agentsFile;
    private final Optional<Path> passwordFile;
    private final TraceLog traceLog;
    private final PlatformChat chat;
    private final PlatformTeleOperation teleOperation;
    private final LiveWorldView world;

    private Platform(KnowledgeStore store, ScriptRuntime scripts, EventLog log, ExecutorService engineThread,
                     ScheduledExecutorService ticker, InferenceEngine engine, GatewayServer gateway,
                     Optional<EditorServer> editor, Path agentsFile, Optional<Path> passwordFile, TraceLog traceLog,
                     PlatformChat chat, PlatformTeleOperation teleOperation, LiveWorldView world) {
        this.store = store;
        this.scripts = scripts;
        this.log = log;
        this.engineThread = engineThread;
        this.ticker = ticker;
        this.engine = engine;
        this.gateway = gateway;
        this.editor = editor;
        this.agentsFile = agentsFile;
        this.passwordFile = passwordFile;
        this.traceLog = traceLog;
        this.chat = chat;
        this.teleOperation = teleOperation;
        this.world = world;
    }

    /** The directory of the platform's own files in a knowledge-base directory. */
    public static Path metaDir(Path kbDir) {
        return kbDir.resolve(KnowledgeStore.META_DIR);
    }

    /** The agent file used when none is given: {@code KB_DIR/.kicnp/agents.properties}. */
    public static Path defaultAgentsFile(Path kbDir) {
        return metaDir(kbDir).resolve("agents.properties");
    }

    /**
     * Opens the knowledge base and starts everything. On failure whatever was started is stopped again.
     *
     * @throws RuntimeException with a sentence saying what could not start
     */
    public static Platform start(PlatformConfig config) {
        Path dir = config.kbDir();
        Path agents = config.agentsFile().orElseGet(() -> defaultAgentsFile(dir));
        if (config.agentsFile().isEmpty() && Secrets.writeAgentsFile(agents)) {
            LOG.info("Wrote agent tokens to '{}'.", agents);
        }
        AgentDirectory directory = AgentDirectory.load(agents);
        Path logFile = config.eventLog().orElseGet(() -> metaDir(dir).resolve("logs")
                .resolve("events-" + STAMP.format(Instant.now()) + ".jsonl"));
        KnowledgeStore store = KnowledgeStore.open(dir);
        EventLog log = null;
        ScriptRuntime scripts = null;
        ExecutorService engineThread = null;
        ScheduledExecutorService ticker = null;
        InferenceEngine engine = null;
        GatewayServer gateway = null;
        PlatformChat chat = null;
        PlatformTeleOperation teleOperation = null;
        try {
            KnowledgeBase kb = store.kb();
            log = EventLog.open(logFile);
            scripts = ScriptRuntime.create(ScriptConfig.defaults().withTimeLimit(SCRIPT_TIME_LIMIT));
            engineThread = Executors.newSingleThreadExecutor(r -> daemon(r, "kicnp-engine"));
            CommandBridge bridge = new CommandBridge(kb, log);
            TraceLog traceLog = new TraceLog(log);
            EngineLink engineLink = new EngineLink(kb, engineThread);
            gateway = GatewayServer.start(GatewayConfig.defaults().withPort(config.gatewayPort())
                    .withTransport(config.gatewayTransport()), directory, kb, bridge,
                    engineLink, engineLink);
            GatewayServer opened = gateway;
            config.agentListener().ifPresent(l -> opened.listenAlso(l.host(), l.port(), l.tls()));
            engine = InferenceEngine.builder(kb).scripts(new GraalScriptHost(scripts)).actionSink(bridge)
                    .runOn(engineThread).build();
            engineLink.attach(engine);
            engine.addTraceListener(traceLog);
            kb.addListener(traceLog);
            bridge.connect(gateway.actionSink(), engine);
            ticker = Executors.newSingleThreadScheduledExecutor(r -> daemon(r, "kicnp-engine-tick"));
            InferenceEngine e = engine;
            ticker.scheduleAtFixedRate(e::tick, 250, 250, TimeUnit.MILLISECONDS);
            GatewayServer g = gateway;
            chat = new PlatformChat(gateway.port(), name -> tokenIn(agents, name), g::registeredAgents, kb, log);
            teleOperation = new PlatformTeleOperation(kb, log, g::registeredAgents, g::actionSink, e::cancelAction);
            LiveWorldView world = new LiveWorldView();
            Optional<EditorServer> editor = Optional.empty();
            Optional<Path> passwordFile = Optional.empty();
            if (config.httpPort().isPresent()) {
                Path pw = config.editorPasswordFile().orElseGet(() -> metaDir(dir).resolve("editor-password"));
                passwordFile = Optional.of(pw);
                editor = Optional.of(EditorServer.start(EditorConfig.defaults().withPort(config.httpPort().get())
                        .withPassword(Secrets.password(pw)), kb, engine,
                        PlatformPorts.none().withChat(chat).withTeleOperation(teleOperation).withWorld(world)));
            }
            engine.tick();
            log.record("started", Map.of("kb", dir.toString(), "gateway", gateway.port(),
                    "editor", editor.map(EditorServer::port).orElse(-1)));
            return new Platform(store, scripts, log, engineThread, ticker, engine, gateway, editor, agents,
                    passwordFile, traceLog, chat, teleOperation, world);
        } catch (RuntimeException ex) {
            if (ticker != null) {
                ticker.shutdownNow();
            }
            if (chat != null) {
                chat.close();
            }
            if (teleOperation != null) {
                teleOperation.close();
            }
            if (gateway != null) {
                gateway.close();
            }
            if (engine != null) {
                engine.close();
            }
            if (engineThread != null) {
                engineThread.shutdownNow();
            }
            if (scripts != null) {
                scripts.close();
            }
            if (log != null) {
                log.close();
            }
            store.close();
            throw ex;
        }
    }

    private static Thread daemon(Runnable r, String name) {
        Thread t = new Thread(r, name);
        t.setDaemon(true);
        return t;
    }

    public KnowledgeBase kb() {
        return store.kb();
    }

    public InferenceEngine engine() {
        return engine;
    }

    public GatewayServer gateway() {
        return gateway;
    }

    public int gatewayPort() {
        return gateway.port();
    }

    /** The gateway's further address for agents on other machines ({@link PlatformConfig.AgentListener}), if any. */
    public Optional<InetSocketAddress> agentListenerAddress() {
        return gateway.moreAddresses().stream().findFirst();
    }

    public Transport gatewayTransport() {
        return gateway.transport();
    }

    /** The editor's port, when it runs. */
    public Optional<Integer> editorPort() {
        return editor.map(EditorServer::port);
    }

    public Path agentsFile() {
        return agentsFile;
    }

    public Optional<Path> editorPasswordFile() {
        return passwordFile;
    }

    public EventLog events() {
        return log;
    }

    /** The chat port the editor uses: a person's words to the sentence parser, the verdicts and robots' lines back. */
    public ChatPort chat() {
        return chat;
    }

    /** The tele-operation port the editor uses: commands by hand, their feedback, judgements of wrong actions. */
    public TeleOperation teleOperation() {
        return teleOperation;
    }

    /**
     * The world view the editor's World panel shows: empty until a simulator is {@linkplain LiveWorldView#attach
     * attached} ({@code demo} and {@code replay} attach theirs once it runs).
     */
    public LiveWorldView world() {
        return world;
    }

    /** The agent directory's token for an agent, read from the agent file. */
    public String token(String agent) {
        return tokenIn(agentsFile, agent).orElseThrow(() -> new IllegalArgumentException(
                "The agent file '" + agentsFile + "' has no token for '" + agent + "'."));
    }

    private static Optional<String> tokenIn(Path agentsFile, String agent) {
        try (var r = java.nio.file.Files.newBufferedReader(agentsFile)) {
            java.util.Properties p = new java.util.Properties();
            p.load(r);
            return Optional.ofNullable(p.getProperty(agent + ".token")).map(String::strip);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException("Cannot read the agent file '" + agentsFile + "'.", e);
        }
    }

    @Override public void close() {
        log.record("stopping", Map.of());
        ticker.shutdownNow();
        editor.ifPresent(EditorServer::close);
        chat.close();
        teleOperation.close();
        gateway.close();
        store.kb().removeListener(traceLog);
        engine.close();
        engineThread.shutdown();
        try {
            engineThread.awaitTermination(5, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        scripts.close();
        store.close();
        log.close();
    }
}
