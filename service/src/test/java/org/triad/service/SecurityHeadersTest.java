package org.triad.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Path;
import java.time.Duration;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Pages and API answers carry a content security policy and refuse framing; cross-origin access stays closed. */
class SecurityHeadersTest {
    @TempDir
    static Path dir;
    private static ServiceFixture s;
    private static final HttpClient HTTP = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();

    @BeforeAll
    static void start() {
        s = ServiceFixture.start(dir.resolve("db"), "dry:1");
    }

    @AfterAll
    static void stop() {
        s.close();
    }

    private static HttpResponse<String> send(HttpRequest.Builder b) throws Exception {
        return HTTP.send(b.timeout(Duration.ofSeconds(30)).build(), HttpResponse.BodyHandlers.ofString());
    }

    @Test
    void pagesAndAnswersCarryThePolicyAndRefuseFrames() throws Exception {
        for (String path : new String[] { "/", "/operator.html", "/triad.js", "/api/openapi.json", "/api/tasks" }) {
            HttpResponse<String> r = send(HttpRequest.newBuilder(URI.create(s.service.url() + path)));
            String csp = r.headers().firstValue("Content-Security-Policy").orElse("");
            assertTrue(csp.contains("frame-ancestors 'none'") && csp.contains("script-src 'self'"), path + ": " + csp);
            assertEquals("DENY", r.headers().firstValue("X-Frame-Options").orElse(""), path);
            assertEquals("nosniff", r.headers().firstValue("X-Content-Type-Options").orElse(""), path);
        }
    }

    @Test
    void corsIsClosed() throws Exception {
        HttpResponse<String> get = send(HttpRequest.newBuilder(URI.create(s.service.url() + "/api/tasks")).header("Origin", "http://evil.example")
                .header("Authorization", "Bearer " + ServiceFixture.SUBMIT));
        assertTrue(get.headers().firstValue("Access-Control-Allow-Origin").isEmpty(), get.headers().toString());
        HttpResponse<String> preflight = send(HttpRequest.newBuilder(URI.create(s.service.url() + "/api/tasks"))
                .method("OPTIONS", HttpRequest.BodyPublishers.noBody()).header("Origin", "http://evil.example")
                .header("Access-Control-Request-Method", "POST").header("Access-Control-Request-Headers", "authorization"));
        assertTrue(preflight.headers().firstValue("Access-Control-Allow-Origin").isEmpty(), preflight.headers().toString());
        assertTrue(preflight.headers().firstValue("Access-Control-Allow-Headers").isEmpty(), preflight.headers().toString());
    }
}
