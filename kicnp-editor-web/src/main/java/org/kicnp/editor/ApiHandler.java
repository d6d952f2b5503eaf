package org.kicnp.editor;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.eclipse.jetty.http.HttpHeader;
import org.eclipse.jetty.http.HttpField;
import org.eclipse.jetty.server.Handler;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.util.BufferUtil;
import org.eclipse.jetty.util.Callback;
import org.kicnp.core.BatchRejectedException;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.KnowledgeException;
import org.kicnp.core.StaleRevisionException;
import org.kicnp.core.UnknownFrameException;
import org.kicnp.inference.QuestionTooBroadException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The JSON API under {@code /api/} as a Jetty core handler: routes a request to its resource, enforces the write
 * rules (JSON content type, same origin, logged in) and maps every failure to an HTTP status and a JSON body
 * {@code {"error": sentence, "problems": [...]}}: 400 bad request, 401 not logged in, 403 foreign origin,
 * 404 unknown frame, 409 stale revision, 422 validation problems, 429 too many wrong passwords, 501 feature not in
 * this build, 503 no platform connected (the World panel's resources).
 */
final class ApiHandler extends Handler.Abstract {
    private static final Logger LOG = LoggerFactory.getLogger(ApiHandler.class);

    private final KnowledgeBase kb;
    private final ObjectMapper json;
    private final FrameResource frames;
    private final LoginResource login;
    private final Features features;
    private final PlatformResource platform;

    ApiHandler(KnowledgeBase kb, ObjectMapper json, Sessions sessions, Features features, PlatformResource platform) {
        this.platform = platform;
        this.kb = kb;
        this.json = json;
        this.frames = new FrameResource(kb, features.inference(), features.scripts());
        this.login = new LoginResource(sessions, new LoginThrottle(java.time.Clock.systemUTC()));
        this.features = features;
    }

    @Override public boolean handle(Request request, Response response, Callback callback) {
        String path = Request.getPathInContext(request);
        if (!path.startsWith("/api/")) {
            return false;
        }
        Reply reply;
        ApiRequest api = null;
        try {
            String[] segments = Arrays.stream(path.substring(5).split("/")).filter(s -> !s.isEmpty())
                    .toArray(String[]::new);
            boolean write = !request.getMethod().equals("GET") && !request.getMethod().equals("HEAD");
            if (write) {
                checkWriteIsSafe(request);
            }
            boolean editor = login.loggedIn(request);
            api = new ApiRequest(request, json, segments, editor);
            if (write && !isLoginRoute(segments) && !editor) {
                throw new ApiException(401, login.editingPossible()
                        ? "Log in to edit: the editor is read-only without a login."
                        : "Editing is disabled: no editor password is configured (editor.password), so the editor "
                                + "is read-only.");
            }
            reply = route(api);
        } catch (ApiException e) {
            reply = error(e.status(), e.getMessage(), e.problems());
        } catch (StaleRevisionException e) {
            reply = error(409, e.getMessage(), List.of(ApiProblem.of(e.frame(), "", e.getMessage())));
        } catch (BatchRejectedException e) {
            reply = error(422, e.getMessage(), e.problems().stream().map(ApiProblem::of).toList());
        } catch (UnknownFrameException e) {
            reply = error(404, e.getMessage(), List.of());
        } catch (KnowledgeException e) {
            reply = error(422, e.getMessage(), List.of(ApiProblem.of("", "", e.getMessage())));
        } catch (QuestionTooBroadException e) {
            reply = error(422, e.getMessage(), List.of());
        } catch (RuntimeException e) {
            LOG.error("Editor API request {} {} failed", request.getMethod(), path, e);
            reply = error(500, "The editor failed on this request: " + e.getMessage(), List.of());
        }
        if (reply.status() >= 400 && hasBody(request) && (api == null || !api.bodyRead())) {
            // Refused before its body was read (not JSON, another origin, too large, not logged in): the server then
            // closes the connection rather than read a body it refused, so it says so, and no client sends its next
            // request on a connection that is closing (seen as "header parser received no bytes").
            reply = reply.withHeader(HttpHeader.CONNECTION.asString(), "close");
        }
        write(response, callback, reply);
        return true;
    }

    private Reply route(ApiRequest r) {
        String[] s = r.segments();
        String m = r.method();
        String first = s.length == 0 ? "" : s[0];
        return switch (first) {
            case "session" -> only(m, "GET", () -> {
                Map<String, Object> session = login.status(r, features);
                session.putAll(platform.status());
                return ok(session);
            });
            case "login" -> only(m, "POST", () -> login.login(r));
            case "logout" -> only(m, "POST", () -> login.logout(r));
            case "status" -> only(m, "GET", () -> ok(status()));
            case "frames" -> frames(r, s, m);
            case "export" -> only(m, "GET", () -> {
                Reply xml = features.xml().exportXml(kb);
                return r.query("download").isPresent()
                        ? xml.withHeader("Content-Disposition", "attachment; filename=\"knowledge.xml\"") : xml;
            });
            case "import" -> only(m, "POST", () -> ok(features.xml().importXml(kb, r.body())));
            case "inference" -> inference(r, s, m);
            case "world" -> s.length == 1 ? only(m, "GET", () -> platform.world().map(this::ok)
                    .orElseGet(() -> Reply.json(204, ""))) : notFound(r);
            case "chat" -> s.length != 1 ? notFound(r) : switch (m) {
                case "GET" -> ok(Map.of("lines", platform.chatLines()));
                case "POST" -> withStatus(202, platform.say(r.body()));
                default -> notAllowed(m);
            };
            case "robots" -> robots(r, s, m);
            case "commands" -> s.length == 1 ? only(m, "GET", () -> ok(platform.commands())) : notFound(r);
            case "actions" -> s.length != 3 ? notFound(r) : switch (s[2]) {
                case "wrong" -> only(m, "POST", () -> ok(platform.wrong(s[1], r.body())));
                case "stop" -> only(m, "POST", () -> ok(platform.stop(s[1], r.body())));
                default -> notFound(r);
            };
            case "scripts" -> s.length == 2 && s[1].equals("check")
                    ? only(m, "POST", () -> ok(features.scripts().check(r.body())))
                    : notFound(r);
            default -> notFound(r);
        };
    }

    private Reply frames(ApiRequest r, String[] s, String m) {
        if (s.length == 1) {
            return switch (m) {
                case "GET" -> ok(frames.list(r.query("q")));
                case "POST" -> withStatus(201, frames.create(r.body()));
                default -> notAllowed(m);
            };
        }
        String name = s[1];
        if (s.length == 2) {
            return switch (m) {
                case "GET" -> ok(frames.get(name));
                case "PUT" -> ok(frames.replace(name, r.body()));
                case "DELETE" -> {
                    FrameResource.Deleted d = frames.delete(name);
                    yield ok(Map.of("version", d.version(), "deleted", name, "removed", d.removed()));
                }
                default -> notAllowed(m);
            };
        }
        if (s.length == 3 && s[2].equals("rename")) {
            return only(m, "POST", () -> ok(frames.rename(name, r.body())));
        }
        return notFound(r);
    }

    private Reply robots(ApiRequest r, String[] s, String m) {
        if (s.length == 1) {
            return only(m, "GET", () -> ok(platform.robots()));
        }
        if (s.length == 3 && s[2].equals("commands")) {
            return only(m, "POST", () -> withStatus(202, platform.send(s[1], r.body())));
        }
        return notFound(r);
    }

    private Reply inference(ApiRequest r, String[] s, String m) {
        Features.Inference engine = features.inference();
        if (s.length == 1) {
            return only(m, "GET", () -> ok(engine.status()));
        }
        return switch (s[1]) {
            case "why" -> s.length == 3 ? only(m, "GET", () -> ok(engine.why(s[2]))) : notFound(r);
            case "ask" -> only(m, "GET", () -> ok(engine.ask(r.query("class").orElseThrow(() ->
                    new ApiException(400, "Asking needs the class to ask about: ?class=Name.")))));
            case "prove" -> only(m, "GET", () -> ok(engine.prove(r.query("class").orElseThrow(() ->
                    new ApiException(400, "Proving needs the class to prove: ?class=Name.")))));
            case "why-not" -> only(m, "GET", () -> ok(engine.whyNot(r.query("frame").orElseThrow(() ->
                    new ApiException(400, "Why-not needs the behavior frame to ask about: ?frame=Name.")))));
            case "run" -> only(m, "POST", () -> ok(engine.run()));
            default -> notFound(r);
        };
    }

    private Map<String, Object> status() {
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("version", kb.version());
        out.put("frames", kb.size());
        return out;
    }

    private static boolean isLoginRoute(String[] s) {
        return s.length == 1 && (s[0].equals("login") || s[0].equals("logout"));
    }

    /**
     * CSRF defence in depth, on top of the SameSite=Strict session cookie: a write must be JSON (a cross-site
     * form cannot send that without a CORS preflight, which this server never grants) and, when the browser says
     * where it comes from, come from this very origin.
     */
    private static void checkWriteIsSafe(Request request) {
        String type = request.getHeaders().get(HttpHeader.CONTENT_TYPE);
        boolean bodyless = request.getMethod().equals("DELETE") && type == null;
        if (!bodyless && (type == null || !type.toLowerCase(Locale.ROOT).startsWith("application/json"))) {
            throw new ApiException(415, "Changes must be sent as JSON (Content-Type: application/json).");
        }
        String origin = request.getHeaders().get(HttpHeader.ORIGIN);
        if (origin != null && !sameOrigin(origin, request)) {
            throw new ApiException(403, "Changes from another site (" + origin + ") are refused.");
        }
    }

    private static boolean hasBody(Request request) {
        return request.getLength() > 0 || request.getHeaders().contains(HttpHeader.TRANSFER_ENCODING);
    }

    static boolean sameOrigin(String origin, Request request) {
        try {
            URI o = URI.create(origin);
            String host = request.getHeaders().get(HttpHeader.HOST);
            return host != null && o.getRawAuthority() != null && o.getRawAuthority().equalsIgnoreCase(host);
        } catch (IllegalArgumentException e) {
            return false;
        }
    }

    private Reply only(String method, String allowed, java.util.function.Supplier<Reply> body) {
        return method.equals(allowed) ? body.get() : notAllowed(method);
    }

    private static Reply notAllowed(String method) {
        throw new ApiException(405, "Method " + method + " is not allowed here.");
    }

    private static Reply notFound(ApiRequest r) {
        throw new ApiException(404, "There is no API resource /api/" + String.join("/", r.segments()) + ".");
    }

    private Reply ok(Object body) {
        return withStatus(200, body);
    }

    private Reply withStatus(int status, Object body) {
        try {
            return Reply.json(status, json.writeValueAsString(body));
        } catch (JsonProcessingException e) {
            throw new EditorException("An answer could not be written as JSON: " + e.getMessage(), e);
        }
    }

    private Reply error(int status, String message, List<ApiProblem> problems) {
        Map<String, Object> body = new LinkedHashMap<>();
        body.put("error", message);
        body.put("problems", problems);
        return withStatus(status, body);
    }

    static void write(Response response, Callback callback, Reply reply) {
        response.setStatus(reply.status());
        response.getHeaders().put(HttpHeader.CONTENT_TYPE, reply.contentType());
        response.getHeaders().put(HttpHeader.CACHE_CONTROL, "no-store");
        response.getHeaders().put(new HttpField("X-Content-Type-Options", "nosniff"));
        reply.cookies().forEach(c -> Response.addCookie(response, c));
        reply.headers().forEach((name, value) -> response.getHeaders().put(name, value));
        response.write(true, BufferUtil.toBuffer(reply.body().getBytes(StandardCharsets.UTF_8)), callback);
    }
}
