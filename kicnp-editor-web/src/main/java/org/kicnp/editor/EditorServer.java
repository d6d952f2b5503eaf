package org.kicnp.editor;

import static java.util.Objects.requireNonNull;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.time.Clock;
import java.time.Duration;
import org.eclipse.jetty.server.Handler;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.server.Server;
import org.eclipse.jetty.server.ServerConnector;
import org.eclipse.jetty.server.handler.ContextHandler;
import org.eclipse.jetty.util.thread.QueuedThreadPool;
import org.eclipse.jetty.websocket.server.WebSocketUpgradeHandler;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.inference.InferenceEngine;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The running editor: a Jetty 12 server bound to {@link EditorConfig#host()} that serves the page, the JSON API
 * under {@code /api/} and the {@code /api/events} WebSocket; optionally connected to a live platform through
 * {@link PlatformPorts} (the World panel). Start it with {@link #start(EditorConfig,
 * KnowledgeBase)}, ask {@link #port()} for the port it got, and {@link #close()} it when done.
 */
public final class EditorServer implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(EditorServer.class);

    private final Server server;
    private final ServerConnector connector;
    private final KnowledgeBase kb;
    private final EventHub events;
    private final Features features;
    private final PlatformResource platform;

    private EditorServer(Server server, ServerConnector connector, KnowledgeBase kb, EventHub events,
            Features features, PlatformResource platform) {
        this.platform = platform;
        this.server = server;
        this.connector = connector;
        this.kb = kb;
        this.events = events;
        this.features = features;
    }

    /**
     * Starts the editor on the knowledge base with the XML and script features this build has.
     *
     * @throws EditorException when the port cannot be bound
     */
    public static EditorServer start(EditorConfig config, KnowledgeBase kb) {
        return start(config, kb, EditorFeatures.available(), PlatformPorts.none());
    }

    /**
     * Starts the editor with the World panel connected to a live platform through {@code ports}: the room drawn
     * live, the chat with the robots and tele-operation. Ports left out answer 503 and their panel says so.
     *
     * @throws EditorException when the port cannot be bound
     */
    public static EditorServer start(EditorConfig config, KnowledgeBase kb, PlatformPorts ports) {
        return start(config, kb, EditorFeatures.available(), ports);
    }

    /**
     * Starts the editor with the inference view and the World panel: what {@code ./kicnp serve} runs.
     *
     * @throws EditorException when the port cannot be bound
     */
    public static EditorServer start(EditorConfig config, KnowledgeBase kb, InferenceEngine engine,
            PlatformPorts ports) {
        requireNonNull(engine, "engine");
        return start(config, kb, EditorFeatures.available().withInference(new InferenceResource(engine, kb)), ports);
    }

    /**
     * Starts the editor with a view of the inference engine running over {@code kb}: live instances, agenda,
     * explanations, questions, runs, and the trace pushed over {@code /api/events}.
     *
     * @throws EditorException when the port cannot be bound
     */
    public static EditorServer start(EditorConfig config, KnowledgeBase kb, InferenceEngine engine) {
        requireNonNull(engine, "engine");
        return start(config, kb, engine, PlatformPorts.none());
    }

    static EditorServer start(EditorConfig config, KnowledgeBase kb, Features features, PlatformPorts ports) {
        requireNonNull(config, "config");
        requireNonNull(kb, "kb");
        requireNonNull(ports, "ports");
        PlatformResource platform = new PlatformResource(ports);
        ObjectMapper json = new ObjectMapper();
        Sessions sessions = new Sessions(config.password(), config.sessionLifetime(), Clock.systemUTC());
        EventHub events = new EventHub(kb, json);

        QueuedThreadPool threads = new QueuedThreadPool(32, 4);
        threads.setName("kicnp-editor");
        Server server = new Server(threads);
        ServerConnector connector = new ServerConnector(server, 1, 1);
        connector.setHost(config.host());
        connector.setPort(config.port());
        server.addConnector(connector);

        ContextHandler context = new ContextHandler("/");
        WebSocketUpgradeHandler ws = WebSocketUpgradeHandler.from(server, context, container -> {
            container.setIdleTimeout(Duration.ofMinutes(30));
            container.addMapping("/api/events", (request, response, callback) -> {
                String origin = request.getHeaders().get("Origin");
                if (origin != null && !ApiHandler.sameOrigin(origin, request)) {
                    Response.writeError(request, response, callback, 403, "Event stream from another site refused.");
                    return null;
                }
                return new EventClient(events);
            });
        });
        ws.setHandler(new Handler.Sequence(new ApiHandler(kb, json, sessions, features, platform), new StaticResources()));
        context.setHandler(ws);
        server.setHandler(new HostGuard(config.host(), context));
        kb.addListener(events);
        features.inference().attach(events);
        platform.attach(events);
        try {
            server.start();
        } catch (Exception e) {
            kb.removeListener(events);
            features.inference().close();
            platform.close();
            stopQuietly(server);
            throw new EditorException("The editor could not start on " + config.host() + ":" + config.port() + ": "
                    + e.getMessage(), e);
        }
        EditorServer editor = new EditorServer(server, connector, kb, events, features, platform);
        LOG.info("Knowledge editor at http://{}:{}/ ({})", config.host(), editor.port(),
                sessions.editingPossible() ? "editing after login" : "read-only: no editor.password set");
        return editor;
    }

    /** The TCP port the editor listens on (the one chosen when the configuration asked for port 0). */
    public int port() {
        return connector.getLocalPort();
    }

    /** Stops the server, stops listening to the knowledge base and closes the script runtime if one was started. */
    @Override public void close() {
        kb.removeListener(events);
        features.inference().close();
        platform.close();
        stopQuietly(server);
        if (features.scripts() instanceof AutoCloseable c) {
            try {
                c.close();
            } catch (Exception e) {
                LOG.warn("The editor's script checker did not close cleanly", e);
            }
        }
    }

    private static void stopQuietly(Server server) {
        try {
            server.stop();
        } catch (Exception e) {
            LOG.warn("The editor did not stop cleanly", e);
        }
    }
}
