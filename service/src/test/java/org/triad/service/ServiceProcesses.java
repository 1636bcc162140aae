package org.triad.service;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import com.fasterxml.jackson.databind.JsonNode;

/** Service processes ({@link ServiceProcess}) that tests start, kill with SIGKILL and start again; all end with the test. */
final class ServiceProcesses implements AutoCloseable {
    private final List<Process> started = new ArrayList<>();
    private final HttpClient http = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();

    /** A running service process and its address. */
    record Running(Process process, String url, StringBuilder output) {
        /** SIGKILL, as a power cut or the OOM killer would do it; returns once the process is gone. */
        void kill() {
            process.destroyForcibly();
            try {
                process.waitFor(30, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    /** A start: the running process, or the start-up error it printed. */
    record Start(Running running, String error) {
    }

    Start start(String db, String... robots) {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx256m",
                "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("java.class.path"), ServiceProcess.class.getName(), db));
        command.addAll(List.of(robots));
        Process p;
        try {
            p = new ProcessBuilder(command).redirectErrorStream(true).start();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        synchronized (started) {
            started.add(p);
        }
        StringBuilder output = new StringBuilder();
        CompletableFuture<String> first = new CompletableFuture<>();
        Thread reader = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
                for (String line; (line = r.readLine()) != null;) {
                    synchronized (output) {
                        output.append(line).append('\n');
                    }
                    if (line.startsWith("listening ") || line.startsWith("startup error: ")) {
                        first.complete(line);
                    }
                }
            } catch (IOException e) {
                // the process was killed
            }
            first.complete("ended: " + output);
        }, "service-process-output");
        reader.setDaemon(true);
        reader.start();
        String line;
        try {
            line = first.get(120, TimeUnit.SECONDS);
        } catch (Exception e) {
            p.destroyForcibly();
            throw new AssertionError("the service process did not start in 120 s: " + output, e);
        }
        if (line.startsWith("listening ")) {
            return new Start(new Running(p, line.substring("listening ".length()), output), null);
        }
        try {
            p.waitFor(30, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return new Start(null, line);
    }

    Running startOrFail(String db, String... robots) {
        Start s = start(db, robots);
        if (s.running() == null) {
            throw new AssertionError("the service did not start: " + s.error());
        }
        return s.running();
    }

    /** POST /api/tasks; the status and body, or status -1 when the process did not answer. */
    ServiceFixture.Response submit(String url, String task, String argsJson) {
        return submit(url, task, argsJson, null);
    }

    /** With an {@code Idempotency-Key} header (null: none). */
    ServiceFixture.Response submit(String url, String task, String argsJson, String key) {
        HttpRequest.Builder b = HttpRequest.newBuilder(URI.create(url + "/api/tasks")).header("Content-Type", "application/json")
                .POST(HttpRequest.BodyPublishers.ofString("{\"task\": \"" + task + "\", \"args\": " + argsJson + "}"));
        if (key != null) {
            b.header("Idempotency-Key", key);
        }
        return send(b);
    }

    ServiceFixture.Response get(String url, String path) {
        return send(HttpRequest.newBuilder(URI.create(url + path)).GET());
    }

    private ServiceFixture.Response send(HttpRequest.Builder b) {
        b.header("Authorization", "Bearer " + ServiceFixture.OPERATOR).timeout(Duration.ofSeconds(30));
        try {
            HttpResponse<String> r = http.send(b.build(), HttpResponse.BodyHandlers.ofString());
            JsonNode body = r.body().isEmpty() ? null : ServiceFixture.JSON.readTree(r.body());
            return new ServiceFixture.Response(r.statusCode(), body);
        } catch (IOException e) {
            return new ServiceFixture.Response(-1, null);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return new ServiceFixture.Response(-1, null);
        }
    }

    @Override
    public void close() {
        synchronized (started) {
            for (Process p : started) {
                p.destroyForcibly();
                try {
                    p.waitFor(30, TimeUnit.SECONDS);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }
    }
}
