package org.kicnp.editor;

import java.util.List;
import org.eclipse.jetty.http.HttpCookie;

/** What a resource answers: status, content type, body text and cookies to set. Written by {@link ApiHandler}. */
record Reply(int status, String contentType, String body, List<HttpCookie> cookies) {
    static final String JSON = "application/json; charset=utf-8";

    static Reply json(int status, String body) {
        return new Reply(status, JSON, body, List.of());
    }

    Reply withCookie(HttpCookie cookie) {
        List<HttpCookie> all = new java.util.ArrayList<>(cookies);
        all.add(cookie);
        return new Reply(status, contentType, body, all);
    }
}
