package org.kicnp.editor;

import java.util.Locale;
import java.util.Set;
import org.eclipse.jetty.http.HttpHeader;
import org.eclipse.jetty.server.Handler;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.util.Callback;

/**
 * Defends an editor bound to loopback against DNS rebinding: a foreign web page whose name resolves to 127.0.0.1
 * sends its own name in the Host header, so a request is only served when it names a loopback host. An editor
 * deliberately bound to another address accepts any Host.
 */
final class HostGuard extends Handler.Wrapper {
    private static final Set<String> LOOPBACK = Set.of("127.0.0.1", "localhost", "[::1]", "::1");

    private final boolean loopbackOnly;

    HostGuard(String boundHost, Handler next) {
        super(next);
        this.loopbackOnly = isLoopback(boundHost);
    }

    @Override public boolean handle(Request request, Response response, Callback callback) throws Exception {
        if (loopbackOnly && !isLoopback(hostName(request.getHeaders().get(HttpHeader.HOST)))) {
            Response.writeError(request, response, callback, 421,
                    "This editor only answers requests addressed to a loopback host (127.0.0.1 or localhost).");
            return true;
        }
        return super.handle(request, response, callback);
    }

    static boolean isLoopback(String host) {
        return LOOPBACK.contains(host.toLowerCase(Locale.ROOT)) || host.startsWith("127.");
    }

    /** The host part of a Host header: {@code 127.0.0.1:8080} → {@code 127.0.0.1}, {@code [::1]:80} → {@code [::1]}. */
    static String hostName(String hostHeader) {
        if (hostHeader == null) {
            return "";
        }
        String h = hostHeader.strip();
        if (h.startsWith("[")) {
            int end = h.indexOf(']');
            return end < 0 ? h : h.substring(0, end + 1);
        }
        int colon = h.lastIndexOf(':');
        return colon < 0 ? h : h.substring(0, colon);
    }
}
