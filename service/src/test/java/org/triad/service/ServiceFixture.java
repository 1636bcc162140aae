package org.triad.service;

import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.function.Predicate;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/** A service on a free loopback port over the hospital models, and a small HTTP client for it. */
final class ServiceFixture implements AutoCloseable {
    static final Path HOSPITAL = Path.of("../models/hospital/src/main/models").toAbsolutePath().normalize();
    static final ObjectMapper JSON = new ObjectMapper();
    static final String SUBMIT = "submit-token-for-tests";
    static final String OPERATOR = "operator-token-for-tests";

    final TriadService service;
    private final HttpClient http = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();

    private ServiceFixture(TriadService service) {
        this.service = service;
    }

    static ServiceFixture start(Path db, String... robots) {
        return start(options(db, robots));
    }

    static ServiceFixture start(TriadService.Options options) {
        return new ServiceFixture(TriadService.start(options));
    }

    static TriadService.Options options(Path db, String... robots) {
        return new TriadService.Options(HOSPITAL, List.of(robots), null, db, null, "127.0.0.1", 0,
                Map.of(AccessTokens.SUBMIT_ENV, SUBMIT, AccessTokens.OPERATOR_ENV, OPERATOR));
    }

    record Response(int status, JsonNode body) {
    }

    Response get(String path, String token) {
        return send(HttpRequest.newBuilder(uri(path)).GET(), token);
    }

    Response post(String path, String body, String token) {
        return send(HttpRequest.newBuilder(uri(path)).header("Content-Type", "application/json")
                .POST(HttpRequest.BodyPublishers.ofString(body)), token);
    }

    Response delete(String path, String token) {
        return send(HttpRequest.newBuilder(uri(path)).DELETE(), token);
    }

    /** Submits and returns the new task's id (asserting 201). */
    long submit(String task, String argsJson) {
        Response r = post("/api/tasks", "{\"task\": \"" + task + "\", \"args\": " + argsJson + "}", SUBMIT);
        if (r.status() != 201) {
            fail("submission of " + task + " " + argsJson + " answered " + r.status() + " " + r.body());
        }
        return r.body().get("id").asLong();
    }

    JsonNode task(long id) {
        return get("/api/tasks/" + id, SUBMIT).body();
    }

    /** Polls the task until {@code until} holds (at most 60 s). */
    JsonNode awaitTask(long id, Predicate<JsonNode> until) {
        long deadline = System.nanoTime() + Duration.ofSeconds(60).toNanos();
        JsonNode t = task(id);
        while (!until.test(t)) {
            if (System.nanoTime() > deadline) {
                fail("task " + id + " did not get there in 60 s: " + t.toPrettyString());
            }
            sleep(20);
            t = task(id);
        }
        return t;
    }

    JsonNode awaitState(long id, String state) {
        return awaitTask(id, t -> state.equals(t.get("state").asText()));
    }

    private URI uri(String path) {
        return URI.create(service.url() + path);
    }

    private Response send(HttpRequest.Builder b, String token) {
        if (token != null) {
            b.header("Authorization", "Bearer " + token);
        }
        try {
            HttpResponse<String> r = http.send(b.timeout(Duration.ofSeconds(30)).build(), HttpResponse.BodyHandlers.ofString());
            String text = r.body();
            JsonNode body = text.isEmpty() ? null : JSON.readTree(text);
            return new Response(r.statusCode(), body);
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException(e);
        }
    }

    static void sleep(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    @Override
    public void close() {
        service.close();
    }
}
