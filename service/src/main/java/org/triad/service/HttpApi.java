package org.triad.service;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.function.Consumer;

import org.triad.service.AccessTokens.Role;
import org.triad.service.TaskCatalog.InvalidSubmission;
import org.triad.service.Views.LiveEvent;
import org.triad.service.store.TaskState;

import com.fasterxml.jackson.core.JsonProcessingException;
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
    /** Largest request body accepted, bytes: a submission is a few hundred. */
    static final int MAX_BODY = 64 * 1024;
    private static final int MAX_LIST = 1000;

    private final FleetService service;
    private final AccessTokens tokens;
    private final ObjectNode openApi;
    private final ObjectMapper json = new ObjectMapper();
    private final ExecutorService broadcaster = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "triad-live-events");
        t.setDaemon(true);
        return t;
    });
    private final Javalin app;

    HttpApi(FleetService service, AccessTokens tokens, ObjectNode openApi) {
        this.service = service;
        this.tokens = tokens;
        this.openApi = openApi;
        this.app = Javalin.create(config -> {
            config.showJavalinBanner = false;
            config.http.maxRequestSize = MAX_BODY;
            config.jsonMapper(new JavalinJackson(json, false));
            config.staticFiles.add(files -> {
                files.hostedPath = "/";
                files.directory = "/org/triad/service/web";
                files.location = Location.CLASSPATH;
            });
        });
        routes();
    }

    private void routes() {
        app.before("/api/*", ctx -> {
            if (ctx.path().equals("/api/openapi.json")) {
                return;
            }
            if (ctx.contentLength() > MAX_BODY) {
                throw new ServiceError(413, "too-large", "the body has " + ctx.contentLength() + " bytes; at most " + MAX_BODY + " are accepted");
            }
            String presented = bearer(ctx);
            Role role = tokens.roleOf(presented).orElseThrow(() -> new ServiceError(401, "unauthorized",
                    presented == null ? "a token is needed: 'Authorization: Bearer TOKEN' (or ?token=TOKEN)" : "the token is not valid"));
            ctx.attribute("role", role);
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
        app.delete("/api/tasks/{id}", ctx -> ctx.json(service.cancel(id(ctx), role(ctx) == Role.OPERATOR ? "the operator" : "staff")));
        app.post("/api/tasks/{id}/retry", ctx -> {
            operator(ctx);
            ctx.json(service.retry(id(ctx)));
        });
        app.post("/api/tasks/{id}/reassign", ctx -> {
            operator(ctx);
            long id = id(ctx);
            String robot = null;
            if (!ctx.body().isBlank()) {
                JsonNode b = body(ctx);
                JsonNode r = b.get("robot");
                if (r != null && !r.isNull() && !r.isTextual()) {
                    throw new InvalidSubmission(422, "invalid-robot", List.of(new TaskCatalog.FieldError("robot", "expected a robot's name")));
                }
                robot = r == null || r.isNull() || r.textValue().isBlank() ? null : r.textValue();
            }
            ctx.json(service.reassign(id, robot));
        });
        app.post("/api/tasks/{id}/done", ctx -> {
            operator(ctx);
            ctx.json(service.markDone(id(ctx)));
        });
        app.get("/api/robots", ctx -> ctx.json(service.robots()));
        app.get("/api/robots/{name}/floor", ctx -> ctx.json(service.floor(ctx.pathParam("name"))
                .orElseThrow(() -> new ServiceError(404, "no-map", "robot " + ctx.pathParam("name") + " has no floor map (its platform gives none)"))));
        app.post("/api/robots/{name}/offline", ctx -> {
            operator(ctx);
            ctx.json(service.setOnline(ctx.pathParam("name"), false));
        });
        app.post("/api/robots/{name}/online", ctx -> {
            operator(ctx);
            ctx.json(service.setOnline(ctx.pathParam("name"), true));
        });
        app.get("/api/requests", ctx -> ctx.json(service.requests("true".equals(ctx.queryParam("all")))));
        app.get("/api/health", ctx -> ctx.json(service.health()));
        app.sse("/api/events", client -> {
            client.keepAlive();
            Consumer<LiveEvent> listener = e -> {
                try {
                    broadcaster.execute(() -> {
                        if (!client.terminated()) {
                            client.sendEvent(e.type(), e.data());
                        }
                    });
                } catch (RejectedExecutionException stopped) {
                    // the service is stopping
                }
            };
            service.addListener(listener);
            client.onClose(() -> service.removeListener(listener));
            client.sendEvent("hello", Map.of("robots", service.robots()));
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
        app.exception(Exception.class, (e, ctx) -> ctx.status(500).json(error("internal", "the service failed: " + e)));
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

    private static String bearer(Context ctx) {
        String h = ctx.header("Authorization");
        if (h != null && h.regionMatches(true, 0, "Bearer ", 0, 7)) {
            return h.substring(7).strip();
        }
        return ctx.queryParam("token");
    }

    private static Role role(Context ctx) {
        return ctx.attribute("role");
    }

    private static void operator(Context ctx) {
        if (role(ctx) != Role.OPERATOR) {
            throw new ServiceError(403, "forbidden", "this needs the operator token");
        }
    }

    private static long id(Context ctx) {
        try {
            return Long.parseLong(ctx.pathParam("id"));
        } catch (NumberFormatException e) {
            throw new ServiceError(404, "not-found", "no task '" + ctx.pathParam("id") + "' (task ids are numbers)");
        }
    }

    private JsonNode body(Context ctx) {
        String text = ctx.body();
        if (text.length() > MAX_BODY) {
            throw new ServiceError(413, "too-large", "the body is larger than " + MAX_BODY + " bytes");
        }
        try {
            JsonNode n = json.readTree(text);
            if (n == null || n.isMissingNode()) {
                throw new ServiceError(400, "malformed-json", "the body is empty; expected a JSON object");
            }
            return n;
        } catch (JsonProcessingException e) {
            throw new ServiceError(400, "malformed-json", "the body is not JSON: " + e.getOriginalMessage() + " at line "
                    + e.getLocation().getLineNr() + ", column " + e.getLocation().getColumnNr());
        }
    }

    /** Starts listening on {@code host:port} (0: a free port); returns the port. */
    int start(String host, int port) {
        app.start(host, port);
        return app.port();
    }

    void stop() {
        broadcaster.shutdownNow();
        app.stop();
    }
}
