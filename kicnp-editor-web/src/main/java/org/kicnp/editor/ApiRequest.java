package org.kicnp.editor;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.Optional;
import org.eclipse.jetty.http.HttpCookie;
import org.eclipse.jetty.http.HttpHeader;
import org.eclipse.jetty.server.Request;

/**
 * An API request as the resources see it: method, path segments after {@code /api/}, query, JSON body read with
 * a size limit, and whether the caller is logged in. Keeps Jetty's request type out of the resources.
 */
final class ApiRequest {
    static final int MAX_BODY = 8 * 1024 * 1024;
    static final String SESSION_COOKIE = "kicnp_session";

    private final Request request;
    private final ObjectMapper json;
    private final String[] segments;
    private final boolean editor;
    private boolean bodyRead;

    ApiRequest(Request request, ObjectMapper json, String[] segments, boolean editor) {
        this.request = request;
        this.json = json;
        this.segments = segments;
        this.editor = editor;
    }

    String method() {
        return request.getMethod();
    }

    /** The path segments after {@code /api/}, already URL-decoded. */
    String[] segments() {
        return segments;
    }

    boolean editor() {
        return editor;
    }

    /** The client's IP address, for throttling login attempts. */
    String remoteAddress() {
        return Request.getRemoteAddr(request);
    }

    Optional<String> query(String name) {
        return Optional.ofNullable(Request.extractQueryParameters(request).getValue(name));
    }

    Optional<String> header(HttpHeader h) {
        return Optional.ofNullable(request.getHeaders().get(h));
    }

    static Optional<String> sessionToken(Request request) {
        for (HttpCookie c : Request.getCookies(request)) {
            if (c.getName().equals(SESSION_COOKIE)) {
                return Optional.of(c.getValue());
            }
        }
        return Optional.empty();
    }

    Optional<String> sessionToken() {
        return sessionToken(request);
    }

    /** Whether the body has been read to its end (a refusal before that leaves it on the connection). */
    boolean bodyRead() {
        return bodyRead;
    }

    /** The body as text, at most {@link #MAX_BODY} bytes. */
    String text() {
        long length = request.getLength();
        if (length > MAX_BODY) {
            throw new ApiException(413, "The request body is " + length + " bytes; the editor accepts at most "
                    + MAX_BODY + ".");
        }
        try (InputStream in = Request.asInputStream(request)) {
            byte[] bytes = in.readNBytes(MAX_BODY + 1);
            if (bytes.length > MAX_BODY) {
                throw new ApiException(413, "The request body is larger than the " + MAX_BODY + " bytes the editor accepts.");
            }
            bodyRead = true;
            return new String(bytes, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new ApiException(400, "The request body could not be read: " + e.getMessage());
        }
    }

    /** The body as a JSON tree. */
    JsonNode body() {
        String text = text();
        if (text.isBlank()) {
            throw new ApiException(400, "The request needs a JSON body.");
        }
        try {
            return json.readTree(text);
        } catch (JsonProcessingException e) {
            throw new ApiException(400, "The request body is not valid JSON (line " + e.getLocation().getLineNr()
                    + ", column " + e.getLocation().getColumnNr() + "): " + e.getOriginalMessage());
        }
    }
}
