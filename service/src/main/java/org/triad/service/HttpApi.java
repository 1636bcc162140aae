package org.triad.service;

import java.time.Instant;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Consumer;

import org.triad.building.traffic.TrafficBoard;
import org.triad.service.auth.AuditLog;
import org.triad.service.auth.FailedLogins;
import org.triad.service.auth.Principal;
import org.triad.service.auth.Role;
import org.triad.service.auth.UserStore;
import org.triad.service.TaskCatalog.InvalidSubmission;
import org.triad.service.Views.LiveEvent;
import org.triad.service.store.TaskState;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import io.javalin.Javalin;
import io.javalin.http.Context;
import io.javalin.http.HttpResponseException;
import io.javalin.http.staticfiles.Location;
import io.javalin.json.JavalinJackson;

/**
 * The HTTP side of the service (Javalin): the JSON API under {@code /api}, the live event stream, and
 * the staff ({@code /}) and operator ({@code /operator.html}) pages. Every error is JSON
 * {@code {"error": CODE, "message": TEXT[, "fields": [...]]}}, never a stack trace.
 */
final class HttpApi {
    /** Largest request body accepted, bytes: a submission is a few hundred (see {@link RequestLimits}). */
    static final int MAX_BODY = RequestLimits.MAX_BODY;
    private static final int MAX_LIST = 1000;
    /** The waits /api/traffic lists without ?over=: longer than this many seconds. */
    static final double TRAFFIC_WAIT_SHOWN = 30;

    private final FleetService service;
    private final AccessTokens tokens;
    private final UserStore users;
    private final AuditLog audit;
    private final FailedLogins failedLogins;
    private final ObjectNode openApi;
    private final ObjectMapper json = RequestLimits.mapper();
    private final EventStreams events = new EventStreams(System.err::println);
    private final Consumer<LiveEvent> eventListener = events::publish;

    /** The live event stream's clients (tests publish through them as the fleet does). */
    EventStreams events() {
        return events;
    }
    private final Javalin app;
    private final HttpsSettings https;
    /** Robots waiting for a corridor, a door or the lift (traffic), for the operator page. */
    private volatile TrafficBoard traffic = new TrafficBoard();
    /** The building's doors and lifts as they last reported (for the operator page). */
    private volatile org.triad.building.DeviceBoard devices = new org.triad.building.DeviceBoard();
    private volatile String listenHost;
    private volatile int listenPort;

    HttpApi(FleetService service, AccessTokens tokens, UserStore users, AuditLog audit, ObjectNode openApi, HttpsSettings https) {
        this.https = https;
        this.service = service;
        this.tokens = tokens;
        this.users = users;
        this.audit = audit;
        this.failedLogins = new FailedLogins(audit);
        this.openApi = openApi;
        this.app = Javalin.create(config -> {
            config.showJavalinBanner = false;
            config.http.maxRequestSize = MAX_BODY;
            if (https != null) {
                // the only connector: Javalin adds its plain HTTP one only when none is configured
                config.jetty.addConnector((server, http) -> https.connector(server, http, listenHost, listenPort));
            }
            config.jsonMapper(new JavalinJackson(json, false));
            config.staticFiles.add(files -> {
                files.hostedPath = "/";
                files.directory = "/org/triad/service/web";
                files.location = Location.CLASSPATH;
            });
        });
        routes();
        service.addListener(eventListener);
    }

    /** Shows the waits of this board under {@code /api/traffic}. */
    private static double waitBound(String over) {
        if (over == null) {
            return TRAFFIC_WAIT_SHOWN;
        }
        try {
            double d = Double.parseDouble(over);
            if (d >= 0 && d < 1e9) {
                return d;
            }
        } catch (NumberFormatException e) {
            // answered below
        }
        throw new ServiceError(400, "bad-request", "?over= takes the seconds a wait must exceed to be listed (at least 0), not '" + over + "'");
    }

    /** Shows the devices of this board under {@code /api/devices}. */
    HttpApi showing(org.triad.building.DeviceBoard board) {
        this.devices = board;
        return this;
    }

    HttpApi showing(TrafficBoard board) {
        this.traffic = board;
        return this;
    }

    private void routes() {
        app.before(SecurityHeaders::apply);
        app.before("/api/*", ctx -> {
            if (ctx.path().equals("/api/openapi.json")) {
                return;
            }
            if (ctx.contentLength() > MAX_BODY) {
                ctx.header("Connection", "close");
                throw new ServiceError(413, "too-large", "the body has " + ctx.contentLength() + " bytes; at most " + MAX_BODY + " are accepted (the body limit)");
            }
            String presented = bearer(ctx);
            Principal principal = authenticate(presented);
            if (principal == null) {
                if (hasBody(ctx)) {
                    ctx.header("Connection", "close"); // its body is never read
                }
                if (presented != null) {
                    failedLogins.record(presented, ctx.method() + " " + ctx.path() + " from " + ctx.ip(), Instant.now());
                }
                throw new ServiceError(401, "unauthorized", presented == null ? "a token is needed: 'Authorization: Bearer TOKEN'"
                        + (ctx.queryParam("token") != null ? " (?token= is accepted only by the event stream /api/events)" : "")
                        : "the token is not valid");
            }
            ctx.attribute("principal", principal);
            if (hasBody(ctx)) {
                ctx.attribute("body", RequestLimits.read(ctx));
            }
        });
        app.before("/api/events", ctx -> {
            String accept = ctx.header("Accept");
            if (accept == null || !accept.contains("text/event-stream")) {
                throw new ServiceError(406, "not-acceptable", "/api/events is a stream of server-sent events: send 'Accept: text/event-stream'");
            }
            if (events.clients() >= EventStreams.MAX_CLIENTS) {
                throw new ServiceError(503, "too-many-streams", "already " + EventStreams.MAX_CLIENTS
                        + " event-stream clients (the limit); try again later");
            }
        });
        app.get("/api/openapi.json", ctx -> ctx.json(openApi));
        app.get("/api/tasks", ctx -> {
            String state = ctx.queryParam("state");
            TaskState filter;
            try {
                filter = state == null || state.isBlank() ? null : TaskState.fromJson(state);
            } catch (IllegalArgumentException e) {
                throw new ServiceError(400, "bad-state", e.getMessage());
            }
            ctx.json(service.tasks(filter, MAX_LIST));
        });
        app.post("/api/tasks", ctx -> {
            String key = ctx.header("Idempotency-Key");
            if (key != null && (key.isBlank() || key.length() > 200)) {
                throw new ServiceError(400, "bad-idempotency-key", "the Idempotency-Key header takes 1 to 200 characters");
            }
            FleetService.Submission s = service.submit(body(ctx), key);
            ctx.status(s.created() ? 201 : 200).json(s.task());
        });
        app.get("/api/tasks/{id}", ctx -> ctx.json(service.task(id(ctx)).orElseThrow(() -> new ServiceError(404, "not-found", "no task " + ctx.pathParam("id")))));
        app.delete("/api/tasks/{id}", ctx -> {
            long id = id(ctx);
            Principal p = principal(ctx);
            ctx.json(service.cancel(id, p.describe()));
            audited(ctx, "cancel", "task " + id);
        });
        app.post("/api/tasks/{id}/retry", ctx -> {
            operator(ctx);
            ctx.json(service.retry(id(ctx)));
            audited(ctx, "retry", "task " + id(ctx));
        });
        app.post("/api/tasks/{id}/reassign", ctx -> {
            operator(ctx);
            long id = id(ctx);
            String robot = null;
            if (!new String(bodyBytes(ctx), java.nio.charset.StandardCharsets.UTF_8).isBlank()) {
                JsonNode b = body(ctx);
                JsonNode r = b.get("robot");
                if (r != null && !r.isNull() && !r.isTextual()) {
                    throw new InvalidSubmission(422, "invalid-robot", List.of(new TaskCatalog.FieldError("robot", "expected a robot's name")));
                }
                robot = r == null || r.isNull() || r.textValue().isBlank() ? null : r.textValue();
            }
            ctx.json(service.reassign(id, robot));
            audited(ctx, "reassign", "task " + id + " to " + (robot == null ? "any robot" : robot));
        });
        app.post("/api/tasks/{id}/done", ctx -> {
            operator(ctx);
            ctx.json(service.markDone(id(ctx)));
            audited(ctx, "mark-done", "task " + id(ctx));
        });
        app.get("/api/robots", ctx -> ctx.json(service.robots()));
        app.get("/api/traffic", ctx -> ctx.json(traffic.longerThan(waitBound(ctx.queryParam("over")))));
        app.get("/api/devices", ctx -> ctx.json(devices.devices()));
        app.get("/api/building", ctx -> ctx.json(service.building()));
        app.get("/api/robots/{name}/floor", ctx -> ctx.json(service.floor(ctx.pathParam("name"))
                .orElseThrow(() -> new ServiceError(404, "no-map", "robot " + ctx.pathParam("name") + " has no floor map (its platform gives none)"))));
        app.post("/api/robots/{name}/offline", ctx -> {
            operator(ctx);
            ctx.json(service.setOnline(ctx.pathParam("name"), false));
            audited(ctx, "robot-offline", "robot " + ctx.pathParam("name"));
        });
        app.post("/api/robots/{name}/online", ctx -> {
            operator(ctx);
            ctx.json(service.setOnline(ctx.pathParam("name"), true));
            audited(ctx, "robot-online", "robot " + ctx.pathParam("name"));
        });
        app.get("/api/audit", ctx -> {
            require(ctx, Role.OPERATOR);
            ctx.json(audit.recent(MAX_LIST));
        });
        app.get("/api/users", ctx -> {
            require(ctx, Role.ADMIN);
            ctx.json(users.list());
        });
        app.post("/api/users", ctx -> {
            require(ctx, Role.ADMIN);
            JsonNode b = body(ctx);
            JsonNode name = b.get("name");
            JsonNode role = b.get("role");
            String token;
            try {
                token = users.add(name == null ? null : name.asText(), Role.of(role == null ? "" : role.asText()), Instant.now());
            } catch (IllegalArgumentException e) {
                throw new ServiceError(422, "invalid-user", e.getMessage());
            }
            audited(ctx, "user-add", name.asText() + " as " + role.asText());
            ctx.status(201).json(Map.of("name", name.asText(), "role", role.asText(), "token", token));
        });
        app.delete("/api/users/{name}", ctx -> {
            require(ctx, Role.ADMIN);
            String name = ctx.pathParam("name");
            if (!users.revoke(name, Instant.now())) {
                throw new ServiceError(404, "not-found", "no user '" + name + "' to revoke (unknown or revoked already)");
            }
            audited(ctx, "user-revoke", name);
            ctx.json(Map.of("name", name, "revoked", true));
        });
        app.get("/api/requests", ctx -> ctx.json(service.requests("true".equals(ctx.queryParam("all")))));
        app.get("/api/health", ctx -> ctx.json(service.health()));
        app.sse("/api/events", client -> {
            client.keepAlive();
            try {
                EventStreams.Subscriber s = events.open(String.valueOf(client.ctx().req().getRemoteAddr()) + ":" + client.ctx().req().getRemotePort(),
                        new EventStreams.Sink() {
                            @Override
                            public void send(String type, Object data) throws java.io.IOException {
                                client.sendEvent(type, data);
                                if (client.terminated()) {
                                    throw new java.io.IOException("the client went away");
                                }
                            }

                            @Override
                            public void close() {
                                client.close();
                            }
                        }, new LiveEvent("hello", Map.of("robots", service.robots())));
                client.onClose(() -> s.drop(null));
            } catch (ServiceError full) {
                client.sendEvent("error", error(full.code(), full.getMessage()));
                client.close();
            }
        });

        app.exception(InvalidSubmission.class, (e, ctx) -> {
            Map<String, Object> body = error(e.code(), e.getMessage());
            body.put("fields", e.errors());
            ctx.status(e.httpStatus()).json(body);
        });
        app.exception(ServiceError.class, (e, ctx) -> ctx.status(e.httpStatus() == 0 ? 500 : e.httpStatus()).json(error(e.code(), e.getMessage())));
        app.exception(HttpResponseException.class, (e, ctx) -> ctx.status(e.getStatus()).json(switch (e.getStatus()) {
            case 404 -> error("not-found", "no endpoint " + ctx.method() + " " + ctx.path());
            case 405 -> error("method-not-allowed", "no endpoint " + ctx.method() + " " + ctx.path());
            case 413 -> error("too-large", "the body is larger than " + MAX_BODY + " bytes");
            default -> error("http-" + e.getStatus(), e.getMessage());
        }));
        app.exception(Exception.class, (e, ctx) -> ctx.status(500).json(error("internal", "the service failed: " + e.getClass().getSimpleName())));
        app.error(404, ctx -> {
            String result = ctx.result();
            if (ctx.path().startsWith("/api") && (result == null || !result.startsWith("{"))) {
                ctx.json(error("not-found", "no endpoint " + ctx.method() + " " + ctx.path()));
            }
        });
        app.error(405, ctx -> {
            if (ctx.path().startsWith("/api")) {
                ctx.json(error("method-not-allowed", "no endpoint " + ctx.method() + " " + ctx.path()));
            }
        });
    }

    private static Map<String, Object> error(String code, String message) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("error", code);
        m.put("message", message);
        return m;
    }

    /** The token: from the Authorization header; from {@code ?token=} only for the event stream (EventSource cannot set headers). */
    private static String bearer(Context ctx) {
        String h = ctx.header("Authorization");
        if (h != null && h.regionMatches(true, 0, "Bearer ", 0, 7)) {
            return h.substring(7).strip();
        }
        return ctx.path().equals("/api/events") ? ctx.queryParam("token") : null;
    }

    private static boolean hasBody(Context ctx) {
        return ctx.contentLength() > 0 || ctx.header("Transfer-Encoding") != null;
    }

    private static byte[] bodyBytes(Context ctx) {
        byte[] b = ctx.attribute("body");
        return b == null ? new byte[0] : b;
    }

    /** The shared tokens first (staff-token, operator-token), then the named users; null if neither knows the token. */
    private Principal authenticate(String presented) {
        if (presented == null) {
            return null;
        }
        Optional<AccessTokens.Role> shared = tokens.roleOf(presented);
        if (shared.isPresent()) {
            return shared.get() == AccessTokens.Role.OPERATOR ? new Principal("operator-token", Role.OPERATOR) : new Principal("staff-token", Role.STAFF);
        }
        return users.authenticate(presented).orElse(null);
    }

    private static Principal principal(Context ctx) {
        return ctx.attribute("principal");
    }

    private static void require(Context ctx, Role needed) {
        Principal p = principal(ctx);
        if (!p.role().allows(needed)) {
            throw new ServiceError(403, "forbidden", "this needs the " + needed.label() + " role; " + p.name() + " is " + p.role().label());
        }
    }

    private static void operator(Context ctx) {
        require(ctx, Role.OPERATOR);
    }

    private void audited(Context ctx, String what, String detail) {
        audit.record(principal(ctx).describe(), what, detail, Instant.now());
    }

    private static long id(Context ctx) {
        try {
            return Long.parseLong(ctx.pathParam("id"));
        } catch (NumberFormatException e) {
            throw new ServiceError(404, "not-found", "no task '" + ctx.pathParam("id") + "' (task ids are numbers)");
        }
    }

    private JsonNode body(Context ctx) {
        return RequestLimits.parse(json, bodyBytes(ctx));
    }

    /** Starts listening on {@code host:port} (0: a free port); returns the port. */
    int start(String host, int port) {
        listenHost = host;
        listenPort = port;
        app.start(host, port);
        return app.port();
    }

    void stop() {
        service.removeListener(eventListener);
        events.close();
        app.stop();
    }
}
