package org.triad.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;

import io.swagger.v3.oas.models.OpenAPI;
import io.swagger.v3.oas.models.media.ComposedSchema;
import io.swagger.v3.oas.models.media.Schema;
import io.swagger.v3.parser.OpenAPIV3Parser;
import io.swagger.v3.parser.core.models.ParseOptions;
import io.swagger.v3.parser.core.models.SwaggerParseResult;

/** The typed task API over the hospital's task models, with dry-run robots: accepted tasks run, bad ones get field-level JSON errors. */
class TaskApiTest {
    @TempDir
    static Path dir;
    static ServiceFixture s;

    @BeforeAll
    static void start() {
        s = ServiceFixture.start(dir.resolve("db"), "dry:2,state=Morning,delay=40");
    }

    @AfterAll
    static void stop() {
        s.close();
    }

    @Test
    void aSubmittedTaskRunsToCompletionWithItsStatusHistory() {
        long id = s.submit("CollectAndDeliver", "{\"i\": \"gauze\", \"from\": \"storage\", \"to\": \"ward1\"}");
        JsonNode t = s.awaitState(id, "completed");
        assertEquals("CollectAndDeliver(gauze, storage, ward1)", t.get("call").asText());
        List<String> kinds = new ArrayList<>();
        t.get("events").forEach(e -> kinds.add(e.get("kind").asText()));
        assertEquals("submitted", kinds.get(0));
        assertEquals("dispatched", kinds.get(1));
        assertTrue(kinds.containsAll(List.of("task_started", "plan_found", "action_started", "action_succeeded", "goal_satisfied")), kinds.toString());
        assertEquals("task_completed", kinds.get(kinds.size() - 1));
        assertTrue(t.get("robot").asText().startsWith("dry-"), t.toString());

        JsonNode list = s.get("/api/tasks?state=completed", ServiceFixture.SUBMIT).body();
        assertTrue(list.isArray());
        boolean listed = false;
        for (JsonNode x : list) {
            listed |= x.get("id").asLong() == id;
        }
        assertTrue(listed, list.toString());
    }

    @Test
    void tasksForDifferentRobotsRunInParallel() {
        long a = s.submit("Patrol", "{\"a\": \"ward2\", \"b\": \"storage\", \"c\": \"ward1\"}");
        long b = s.submit("Patrol", "{\"a\": \"ward1\", \"b\": \"ward3\", \"c\": \"xray\"}");
        long deadline = System.nanoTime() + 30_000_000_000L;
        boolean together = false;
        while (!together && System.nanoTime() < deadline) {
            JsonNode robots = s.get("/api/robots", ServiceFixture.SUBMIT).body();
            together = robots.get(0).hasNonNull("task") && robots.get(1).hasNonNull("task");
            ServiceFixture.sleep(10);
        }
        assertTrue(together, "both robots had a task at the same time");
        assertTrue(!s.awaitState(a, "completed").get("robot").asText().equals(s.awaitState(b, "completed").get("robot").asText()));
    }

    @Test
    void aTaskOnAPersonCompletes() {
        long id = s.submit("Guide", "{\"p\": \"bob\", \"to\": \"lobby\"}");
        assertEquals("completed", s.awaitState(id, "completed").get("state").asText());
    }

    @Test
    void unknownTaskIs422OnTheTaskField() {
        ServiceFixture.Response r = s.post("/api/tasks", "{\"task\": \"Teleport\", \"args\": {}}", ServiceFixture.SUBMIT);
        assertEquals(422, r.status());
        assertEquals("unknown-task", r.body().get("error").asText());
        assertEquals("task", r.body().get("fields").get(0).get("field").asText());
        assertTrue(r.body().get("message").asText().contains("CollectAndDeliver"), r.body().toString());
    }

    @Test
    void missingExtraAndMistypedArgumentsAreEachReported() {
        ServiceFixture.Response r = s.post("/api/tasks", "{\"task\": \"Fetch\", \"args\": {\"i\": 3, \"from\": \"storage\", \"speed\": 2}}",
                ServiceFixture.SUBMIT);
        assertEquals(422, r.status());
        assertEquals("invalid-arguments", r.body().get("error").asText());
        List<String> fields = new ArrayList<>();
        r.body().get("fields").forEach(f -> fields.add(f.get("field").asText()));
        assertEquals(List.of("args.speed", "args.i", "args.to"), fields);
    }

    @Test
    void anObjectThatDoesNotExistOrHasTheWrongTypeIsNamed() {
        ServiceFixture.Response r = s.post("/api/tasks", "{\"task\": \"Fetch\", \"args\": {\"i\": \"scalpel\", \"from\": \"gauze\", \"to\": \"ward1\"}}",
                ServiceFixture.SUBMIT);
        assertEquals(422, r.status());
        JsonNode fields = r.body().get("fields");
        assertEquals("args.i", fields.get(0).get("field").asText());
        assertTrue(fields.get(0).get("message").asText().contains("no object 'scalpel'"), fields.toString());
        assertTrue(fields.get(0).get("message").asText().contains("[gauze, syringe, bandage, insulin]"), fields.toString());
        assertEquals("args.from", fields.get(1).get("field").asText());
        assertTrue(fields.get(1).get("message").asText().contains("'gauze' is a Item, not a Room"), fields.toString());
    }

    @Test
    void malformedJsonIs400WithWhereItBroke() {
        ServiceFixture.Response r = s.post("/api/tasks", "{\"task\": \"GoTo\", \"args\": {\"dst\": ", ServiceFixture.SUBMIT);
        assertEquals(400, r.status());
        assertEquals("malformed-json", r.body().get("error").asText());
        assertTrue(r.body().get("message").asText().contains("line 1"), r.body().toString());
        ServiceFixture.Response array = s.post("/api/tasks", "[1, 2]", ServiceFixture.SUBMIT);
        assertEquals(400, array.status());
        assertEquals("malformed", array.body().get("error").asText());
    }

    @Test
    void anOversizedBodyIs413() {
        String big = "{\"task\": \"GoTo\", \"args\": {\"dst\": \"" + "x".repeat(HttpApi.MAX_BODY) + "\"}}";
        ServiceFixture.Response r = s.post("/api/tasks", big, ServiceFixture.SUBMIT);
        assertEquals(413, r.status());
        assertEquals("too-large", r.body().get("error").asText());
    }

    @Test
    void withoutAValidTokenEverythingButTheOpenApiDocumentIs401() {
        assertEquals(401, s.get("/api/tasks", null).status());
        assertEquals("unauthorized", s.get("/api/tasks", null).body().get("error").asText());
        assertEquals(401, s.post("/api/tasks", "{\"task\": \"GoTo\", \"args\": {\"dst\": \"ward1\"}}", "wrong-token").status());
        assertEquals(401, s.get("/api/robots", "").status());
        assertEquals(200, s.get("/api/openapi.json", null).status());
        // a token in the URL lands in logs and histories: only the event stream takes one (EventSource cannot send headers)
        ServiceFixture.Response inUrl = s.get("/api/tasks?token=" + ServiceFixture.SUBMIT, null);
        assertEquals(401, inUrl.status());
        assertTrue(inUrl.body().get("message").asText().contains("only by the event stream"), inUrl.body().toString());
    }

    @Test
    void operatorActionsNeedTheOperatorToken() {
        long id = s.submit("GoTo", "{\"dst\": \"ward2\"}");
        ServiceFixture.Response r = s.post("/api/tasks/" + id + "/done", "", ServiceFixture.SUBMIT);
        assertEquals(403, r.status());
        assertEquals("forbidden", r.body().get("error").asText());
    }

    @Test
    void unknownTasksAndEndpointsAre404InJson() {
        assertEquals("not-found", s.get("/api/tasks/999999", ServiceFixture.SUBMIT).body().get("error").asText());
        assertEquals(404, s.get("/api/tasks/abc", ServiceFixture.SUBMIT).status());
        assertEquals(404, s.get("/api/nothing", ServiceFixture.SUBMIT).status());
        assertEquals("not-found", s.get("/api/nothing", ServiceFixture.SUBMIT).body().get("error").asText());
    }

    @Test
    void theOpenApiDocumentIsValidOpenApi3WithASchemaPerTaskAndObjectsAsEnums() {
        ServiceFixture.Response r = s.get("/api/openapi.json", null);
        assertEquals(200, r.status());
        ParseOptions options = new ParseOptions();
        options.setResolve(true);
        SwaggerParseResult parsed = new OpenAPIV3Parser().readContents(r.body().toString(), null, options);
        assertEquals(List.of(), parsed.getMessages(), "validator messages");
        OpenAPI api = parsed.getOpenAPI();
        assertEquals("3.0.3", api.getOpenapi());
        for (String task : List.of("GoTo", "Patrol", "Fetch", "Deliver", "CollectAndDeliver", "Guide", "Follow", "Recharge")) {
            assertTrue(api.getComponents().getSchemas().containsKey("Task." + task), task);
        }
        Schema<?> fetchArgs = (Schema<?>) api.getComponents().getSchemas().get("Task.Fetch").getProperties().get("args");
        assertEquals(java.util.Set.of("i", "from", "to"), java.util.Set.copyOf(fetchArgs.getRequired()));
        assertEquals(List.of("gauze", "syringe", "bandage", "insulin"), ((Schema<?>) fetchArgs.getProperties().get("i")).getEnum());
        assertEquals(List.of("storage", "xray", "ward1", "ward2", "ward3", "lobby", "pharmacy", "ward4", "ward5"),
                ((Schema<?>) fetchArgs.getProperties().get("to")).getEnum());
        assertEquals(8, ((ComposedSchema) api.getComponents().getSchemas().get("TaskSubmission")).getOneOf().size());
        assertTrue(api.getPaths().get("/api/tasks").getPost() != null);
    }

    @Test
    void robotsAreListedWithTheirState() {
        JsonNode robots = s.get("/api/robots", ServiceFixture.SUBMIT).body();
        assertEquals(2, robots.size());
        assertEquals("dry-1", robots.get(0).get("name").asText());
        assertTrue(robots.get(0).get("online").asBoolean());
        assertEquals(404, s.get("/api/robots/dry-1/floor", ServiceFixture.SUBMIT).status());
    }
}
