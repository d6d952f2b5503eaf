package org.kicnp.editor;

import java.util.LinkedHashMap;
import java.util.Map;
import org.eclipse.jetty.http.HttpCookie;
import org.eclipse.jetty.http.HttpHeader;
import org.eclipse.jetty.server.Request;

/**
 * Login, logout and "who am I". A correct password opens a session whose token travels in an HttpOnly,
 * SameSite=Strict cookie; scripts may instead send {@code Authorization: Bearer <password>}. A wrong password is
 * refused with a sentence and a short pause; repeated wrong passwords from one address are refused for a while
 * ({@link LoginThrottle}).
 */
final class LoginResource {
    private static final long WRONG_PASSWORD_PAUSE_MS = 300;

    private final Sessions sessions;
    private final LoginThrottle throttle;

    LoginResource(Sessions sessions, LoginThrottle throttle) {
        this.sessions = sessions;
        this.throttle = throttle;
    }

    boolean editingPossible() {
        return sessions.editingPossible();
    }

    /**
     * Whether the request carries a valid session cookie or the right password as a bearer token. A bearer password
     * is a password guess like a login: a wrong one is refused and counted by the same throttle, or every tool could
     * guess without limit.
     *
     * @throws ApiException 401 for a wrong bearer password, 429 while its address is throttled
     */
    boolean loggedIn(Request request) {
        String auth = request.getHeaders().get(HttpHeader.AUTHORIZATION);
        if (auth != null && auth.regionMatches(true, 0, "Bearer ", 0, 7)) {
            String address = Request.getRemoteAddr(request);
            admitOrRefuse(address);
            if (!sessions.matches(auth.substring(7).strip())) {
                refuseWrongPassword(address, "Wrong password in the Authorization header: you were not logged in.");
            }
            throttle.succeeded(address);
            return true;
        }
        return ApiRequest.sessionToken(request).map(sessions::valid).orElse(false);
    }

    Map<String, Object> status(ApiRequest r, Features features) {
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("loggedIn", r.editor());
        out.put("editingPossible", sessions.editingPossible());
        out.put("xml", features.xml().available());
        out.put("scripts", features.scripts().available());
        out.put("inference", features.inference().available());
        return out;
    }

    Reply login(ApiRequest r) {
        if (!sessions.editingPossible()) {
            throw new ApiException(401, "Editing is disabled: no editor password is configured (editor.password).");
        }
        String address = r.remoteAddress();
        admitOrRefuse(address);
        String password = FrameInput.text(r.body(), "password").orElse("");
        if (!sessions.matches(password)) {
            refuseWrongPassword(address, "Wrong password: you were not logged in.");
        }
        throttle.succeeded(address);
        HttpCookie cookie = HttpCookie.build(ApiRequest.SESSION_COOKIE, sessions.open())
                .path("/").httpOnly(true).sameSite(HttpCookie.SameSite.STRICT)
                .maxAge(sessions.lifetime().toSeconds()).build();
        return Reply.json(200, "{\"loggedIn\":true}").withCookie(cookie);
    }

    /** Counts a password guess, or refuses it while the address is throttled. */
    private void admitOrRefuse(String address) {
        long wait = throttle.admit(address);
        if (wait > 0) {
            throw new ApiException(429, "Too many wrong passwords from this address: try again in " + wait
                    + " seconds.");
        }
    }

    /** The guess was counted when it was admitted; a wrong one is only made to wait. */
    private void refuseWrongPassword(String address, String message) {
        try {
            Thread.sleep(WRONG_PASSWORD_PAUSE_MS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        throw new ApiException(401, message);
    }

    Reply logout(ApiRequest r) {
        r.sessionToken().ifPresent(sessions::close);
        HttpCookie expired = HttpCookie.build(ApiRequest.SESSION_COOKIE, "").path("/").httpOnly(true)
                .sameSite(HttpCookie.SameSite.STRICT).maxAge(0).build();
        return Reply.json(200, "{\"loggedIn\":false}").withCookie(expired);
    }
}
