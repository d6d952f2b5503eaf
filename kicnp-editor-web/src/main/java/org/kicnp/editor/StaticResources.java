package org.kicnp.editor;

import java.io.IOException;
import java.io.InputStream;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.eclipse.jetty.http.HttpField;
import org.eclipse.jetty.http.HttpHeader;
import org.eclipse.jetty.server.Handler;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.util.BufferUtil;
import org.eclipse.jetty.util.Callback;

/**
 * Serves the page: a fixed list of files from {@code org/kicnp/editor/web/} on the class path, nothing else (no
 * directory listing, no path arithmetic). Every answer carries a Content-Security-Policy that lets the page load
 * only its own script and style and talk only to this server, so nothing is fetched from the network.
 */
final class StaticResources extends Handler.Abstract {
    static final String CSP = "default-src 'none'; script-src 'self'; style-src 'self'; img-src 'self' data:; "
            + "connect-src 'self'; font-src 'self'; base-uri 'none'; form-action 'none'; frame-ancestors 'none'";
    private static final String ROOT = "org/kicnp/editor/web/";
    private static final Map<String, String> FILES = Map.ofEntries(
            Map.entry("/", "index.html"),
            Map.entry("/index.html", "index.html"),
            Map.entry("/editor.css", "editor.css"),
            Map.entry("/favicon.svg", "favicon.svg"),
            Map.entry("/editor.js", "editor.js"),
            Map.entry("/base.js", "base.js"),
            Map.entry("/tree.js", "tree.js"),
            Map.entry("/links.js", "links.js"),
            Map.entry("/frame.js", "frame.js"),
            Map.entry("/slots.js", "slots.js"),
            Map.entry("/inference.js", "inference.js"),
            Map.entry("/world.js", "world.js"),
            Map.entry("/operate.js", "operate.js"),
            Map.entry("/highlight.js", "highlight.js"));
    private static final Map<String, String> TYPES = Map.of(
            "html", "text/html; charset=utf-8",
            "js", "text/javascript; charset=utf-8",
            "css", "text/css; charset=utf-8",
            "svg", "image/svg+xml");

    private final Map<String, byte[]> cache = new ConcurrentHashMap<>();

    @Override public boolean handle(Request request, Response response, Callback callback) {
        String file = FILES.get(Request.getPathInContext(request));
        if (file == null || !(request.getMethod().equals("GET") || request.getMethod().equals("HEAD"))) {
            return false;
        }
        byte[] bytes = cache.computeIfAbsent(file, StaticResources::read);
        response.setStatus(200);
        response.getHeaders().put(HttpHeader.CONTENT_TYPE, TYPES.get(file.substring(file.lastIndexOf('.') + 1)));
        response.getHeaders().put(HttpHeader.CACHE_CONTROL, "no-cache");
        response.getHeaders().put(new HttpField("Content-Security-Policy", CSP));
        response.getHeaders().put(new HttpField("X-Content-Type-Options", "nosniff"));
        response.getHeaders().put(new HttpField("Referrer-Policy", "no-referrer"));
        response.write(true, request.getMethod().equals("HEAD") ? BufferUtil.EMPTY_BUFFER : BufferUtil.toBuffer(bytes),
                callback);
        return true;
    }

    private static byte[] read(String file) {
        try (InputStream in = StaticResources.class.getClassLoader().getResourceAsStream(ROOT + file)) {
            if (in == null) {
                throw new EditorException("The editor page file '" + file + "' is missing from the class path.");
            }
            return in.readAllBytes();
        } catch (IOException e) {
            throw new EditorException("Cannot read the editor page file '" + file + "': " + e.getMessage(), e);
        }
    }
}
