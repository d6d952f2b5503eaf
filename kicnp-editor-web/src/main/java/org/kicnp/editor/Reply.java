package org.kicnp.editor;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.eclipse.jetty.http.HttpCookie;

/** What a resource answers: status, content type, body text, cookies and extra headers. Written by {@link ApiHandler}. */
record Reply(int status, String contentType, String body, List<HttpCookie> cookies, Map<String, String> headers) {
    static final String JSON = "application/json; charset=utf-8";

    Reply {
        cookies = List.copyOf(cookies);
        headers = Map.copyOf(headers);
    }

    static Reply json(int status, String body) {
        return new Reply(status, JSON, body, List.of(), Map.of());
    }

    static Reply text(int status, String contentType, String body) {
        return new Reply(status, contentType, body, List.of(), Map.of());
    }

    Reply withCookie(HttpCookie cookie) {
        List<HttpCookie> all = new ArrayList<>(cookies);
        all.add(cookie);
        return new Reply(status, contentType, body, all, headers);
    }

    Reply withHeader(String name, String value) {
        Map<String, String> all = new LinkedHashMap<>(headers);
        all.put(name, value);
        return new Reply(status, contentType, body, cookies, all);
    }
}
