package org.kicnp.editor;

import java.util.ArrayDeque;
import java.util.Queue;
import org.eclipse.jetty.websocket.api.Callback;
import org.eclipse.jetty.websocket.api.Session;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One browser listening on {@code /api/events}. Messages are sent one at a time in order (a WebSocket session
 * allows a single pending write); a client that falls more than {@link #MAX_QUEUED} messages behind is closed
 * rather than letting the server buffer without bound, and the page reconnects and reloads.
 *
 * <p>Public only because Jetty binds the listener methods through method handles, which need a public class;
 * the constructor stays package-private.
 */
public final class EventClient extends Session.Listener.AbstractAutoDemanding {
    private static final Logger LOG = LoggerFactory.getLogger(EventClient.class);
    static final int MAX_QUEUED = 1000;

    private final EventHub hub;
    private final Queue<String> queue = new ArrayDeque<>();
    private boolean sending;

    EventClient(EventHub hub) {
        this.hub = hub;
    }

    @Override public void onWebSocketOpen(Session session) {
        super.onWebSocketOpen(session);
        hub.joined(this);
    }

    @Override public void onWebSocketClose(int statusCode, String reason) {
        hub.left(this);
    }

    @Override public void onWebSocketError(Throwable cause) {
        LOG.debug("Editor event socket failed", cause);
        hub.left(this);
    }

    /** Queues a message for this client. */
    void send(String json) {
        synchronized (queue) {
            if (queue.size() >= MAX_QUEUED) {
                LOG.warn("An editor event client fell {} messages behind; closing it", MAX_QUEUED);
                queue.clear();
                getSession().close(1008, "Too slow; reconnect and reload.", Callback.NOOP);
                return;
            }
            queue.add(json);
            if (sending) {
                return;
            }
            sending = true;
        }
        next();
    }

    private void next() {
        String message;
        synchronized (queue) {
            message = queue.poll();
            if (message == null) {
                sending = false;
                return;
            }
        }
        Session s = getSession();
        if (s == null || !s.isOpen()) {
            synchronized (queue) {
                queue.clear();
                sending = false;
            }
            return;
        }
        s.sendText(message, Callback.from(this::next, failure -> {
            LOG.debug("Could not send an editor event", failure);
            hub.left(this);
        }));
    }
}
