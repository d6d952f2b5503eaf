package org.kicnp.editor;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.http.HttpResponse;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Who may use the JSON API, against a real Jetty on an ephemeral loopback port: reads are open and writes need a
 * login or a bearer token; wrong passwords are refused in words and throttled, even when sent at once; writes that
 * are not JSON or come from another origin, and requests naming a foreign host, are refused; an editor without a
 * password is read-only; the page is served with its Content-Security-Policy.
 */
class EditorApiAccessTest extends EditorApiFixture {
    @Test void writes_withoutLogin_answer401WhileReadsWork() {
        assertThat(http.get("/api/frames/Robot").statusCode()).isEqualTo(200);

        HttpResponse<String> r = http.post("/api/frames", "{\"name\":\"Intruder\",\"parent\":\"System\"}");

        assertThat(r.statusCode()).isEqualTo(401);
        assertThat(json(r).get("error").asText()).isEqualTo("Log in to edit: the editor is read-only without a login.");
        assertThat(kb.contains("Intruder")).isFalse();
        assertThat(http.delete("/api/frames/Taro").statusCode()).isEqualTo(401);
    }

    @Test void login_withWrongPassword_isRefusedWithMessageAndGrantsNothing() {
        HttpResponse<String> r = http.login("guess");

        assertThat(r.statusCode()).isEqualTo(401);
        assertThat(json(r).get("error").asText()).isEqualTo("Wrong password: you were not logged in.");
        assertThat(r.headers().firstValue("Set-Cookie")).isEmpty();
        assertThat(http.delete("/api/frames/Taro").statusCode()).isEqualTo(401);
    }

    @Test void login_afterRepeatedWrongPasswords_isRefusedForAWhileEvenWithTheRightOne() {
        for (int i = 0; i < LoginThrottle.MAX_FAILURES; i++) {
            assertThat(http.login("guess " + i).statusCode()).isEqualTo(401);
        }

        HttpResponse<String> r = http.login(PASSWORD);

        assertThat(r.statusCode()).isEqualTo(429);
        assertThat(json(r).get("error").asText()).startsWith("Too many wrong passwords from this address");
        assertThat(r.headers().firstValue("Set-Cookie")).isEmpty();
    }

    @Test void login_withManyWrongPasswordsSentAtOnce_letsOnlyMaxFailuresOfThemBeTried() throws Exception {
        // Every guess's headers arrive before any body does, as a guesser's parallel requests may: the server
        // checks the throttle, then waits for the password.
        int guesses = 40;
        List<java.net.Socket> sockets = new ArrayList<>();
        try {
            for (int i = 0; i < guesses; i++) {
                sockets.add(new java.net.Socket("127.0.0.1", server.port()));
            }
            List<String> bodies = new ArrayList<>();
            for (int i = 0; i < guesses; i++) {
                bodies.add("{\"password\":\"guess " + i + "\"}");
                sockets.get(i).getOutputStream().write(("POST /api/login HTTP/1.1\r\nHost: 127.0.0.1:" + server.port()
                        + "\r\nContent-Type: application/json\r\nContent-Length: " + bodies.get(i).length()
                        + "\r\nConnection: close\r\n\r\n").getBytes(java.nio.charset.StandardCharsets.UTF_8));
            }
            Thread.sleep(300);
            for (int i = 0; i < guesses; i++) {
                sockets.get(i).getOutputStream().write(bodies.get(i).getBytes(java.nio.charset.StandardCharsets.UTF_8));
            }
            List<Integer> statuses = new ArrayList<>();
            for (java.net.Socket socket : sockets) {
                socket.setSoTimeout(30_000);
                String statusLine = new java.io.BufferedReader(new java.io.InputStreamReader(socket.getInputStream(),
                        java.nio.charset.StandardCharsets.UTF_8)).readLine();
                statuses.add(Integer.parseInt(statusLine.split(" ")[1]));
            }

            assertThat(statuses).filteredOn(s -> s == 401).as("guesses compared with the password")
                    .hasSize(LoginThrottle.MAX_FAILURES);
            assertThat(statuses).filteredOn(s -> s == 429).hasSize(guesses - LoginThrottle.MAX_FAILURES);
        } finally {
            for (java.net.Socket socket : sockets) {
                socket.close();
            }
        }
    }

    @Test void login_setsHttpOnlyStrictCookie_andLogoutEndsTheSession() {
        HttpResponse<String> r = http.login(PASSWORD);

        assertThat(r.statusCode()).isEqualTo(200);
        assertThat(r.headers().firstValue("Set-Cookie")).hasValueSatisfying(c -> assertThat(c)
                .contains("HttpOnly").containsIgnoringCase("SameSite=Strict"));
        assertThat(json(http.get("/api/session")).get("loggedIn").asBoolean()).isTrue();
        String session = r.headers().firstValue("Set-Cookie").orElseThrow().split(";", 2)[0];

        http.post("/api/logout", "{}");

        HttpResponse<String> after = http.send(http.jsonRequest("/api/frames/Taro").header("Cookie", session).DELETE());
        assertThat(after.statusCode()).isEqualTo(401);
    }

    @Test void delete_withoutBodyOrContentType_worksWhenLoggedIn() {
        http.login(PASSWORD);

        HttpResponse<String> r = http.send(java.net.http.HttpRequest.newBuilder(
                java.net.URI.create("http://127.0.0.1:" + server.port() + "/api/frames/Taro")).DELETE());

        assertThat(r.statusCode()).as(r.body()).isEqualTo(200);
        assertThat(kb.contains("Taro")).isFalse();
    }

    @Test void bearerToken_allowsEditingWithoutCookie() {
        HttpResponse<String> r = http.send(http.jsonRequest("/api/frames/Taro")
                .header("Authorization", "Bearer " + PASSWORD).DELETE());

        assertThat(r.statusCode()).as(r.body()).isEqualTo(200);
        assertThat(kb.contains("Taro")).isFalse();
    }

    @Test void bearerToken_withWrongPasswords_isRefusedInWordsAndThrottledLikeALogin() {
        HttpResponse<String> first = null;
        for (int i = 0; i < LoginThrottle.MAX_FAILURES; i++) {
            HttpResponse<String> r = http.send(http.jsonRequest("/api/frames/Taro")
                    .header("Authorization", "Bearer guess " + i).DELETE());
            first = first == null ? r : first;
        }

        HttpResponse<String> right = http.send(http.jsonRequest("/api/frames/Taro")
                .header("Authorization", "Bearer " + PASSWORD).DELETE());

        assertThat(first.statusCode()).isEqualTo(401);
        assertThat(json(first).get("error").asText())
                .isEqualTo("Wrong password in the Authorization header: you were not logged in.");
        assertThat(right.statusCode()).as(right.body()).isEqualTo(429);
        assertThat(json(right).get("error").asText()).startsWith("Too many wrong passwords from this address");
        assertThat(kb.contains("Taro")).isTrue();
    }

    @Test void writes_notJsonOrFromAnotherOrigin_areRefused() {
        http.login(PASSWORD);

        HttpResponse<String> form = http.send(http.jsonRequest("/api/frames").setHeader("Content-Type", "text/plain")
                .POST(java.net.http.HttpRequest.BodyPublishers.ofString("{\"name\":\"X\"}")));
        HttpResponse<String> foreign = http.send(http.jsonRequest("/api/frames").header("Origin", "http://evil.example")
                .POST(java.net.http.HttpRequest.BodyPublishers.ofString("{\"name\":\"X\",\"parent\":\"System\"}")));

        assertThat(form.statusCode()).isEqualTo(415);
        assertThat(foreign.statusCode()).isEqualTo(403);
        assertThat(kb.contains("X")).isFalse();
        // refused unread, so the server says it closes the connection: no request follows on it and gets nothing
        assertThat(form.headers().firstValue("Connection")).contains("close");
        assertThat(foreign.headers().firstValue("Connection")).contains("close");
    }

    @Test void request_namingAForeignHost_isRefused_againstDnsRebinding() throws Exception {
        try (java.net.Socket socket = new java.net.Socket("127.0.0.1", server.port())) {
            socket.getOutputStream().write(("GET /api/frames HTTP/1.1\r\nHost: evil.example:" + server.port()
                    + "\r\nConnection: close\r\n\r\n").getBytes(java.nio.charset.StandardCharsets.US_ASCII));
            String answer = new String(socket.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);

            assertThat(answer).startsWith("HTTP/1.1 421").doesNotContain("AskUserName");
        }
        assertThat(http.send(java.net.http.HttpRequest.newBuilder(java.net.URI.create(
                "http://localhost:" + server.port() + "/api/frames"))).statusCode()).isEqualTo(200);
    }

    @Test void readOnlyEditor_withoutPassword_refusesLogin() {
        try (EditorServer readOnly = EditorServer.start(EditorConfig.defaults().withPort(0), kb)) {
            Http other = new Http(readOnly.port());

            HttpResponse<String> r = other.login("anything");

            assertThat(r.statusCode()).isEqualTo(401);
            assertThat(json(r).get("error").asText()).contains("no editor password is configured");
            assertThat(json(other.get("/api/session")).get("editingPossible").asBoolean()).isFalse();
        }
    }

    @Test void page_isServedWithContentSecurityPolicy() {
        HttpResponse<String> r = http.get("/");

        assertThat(r.statusCode()).isEqualTo(200);
        assertThat(r.body()).contains("<title>K-ICNP knowledge editor</title>");
        assertThat(r.headers().firstValue("Content-Security-Policy")).hasValueSatisfying(c ->
                assertThat(c).contains("default-src 'none'").contains("connect-src 'self'"));
        assertThat(http.get("/../pom.xml").statusCode()).isNotEqualTo(200);
    }
}
