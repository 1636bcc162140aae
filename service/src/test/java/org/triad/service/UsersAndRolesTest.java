package org.triad.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Instant;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.service.auth.Role;
import org.triad.service.auth.UserStore;
import org.triad.service.store.TaskStore;

/** Named users with roles on a running service: revoked is 401, staff is 403 on operator actions, the audit log names who did what. */
class UsersAndRolesTest {
    @TempDir
    static Path dir;
    private static ServiceFixture s;
    private static String alice;
    private static String bob;
    private static String carol;
    private static String root;

    @BeforeAll
    static void start() {
        Path db = dir.resolve("db");
        // made before the service starts, as ./triad users does
        try (TaskStore store = TaskStore.open(db)) {
            UserStore users = new UserStore(store);
            alice = users.add("alice", Role.OPERATOR, Instant.now());
            bob = users.add("bob", Role.STAFF, Instant.now());
            carol = users.add("carol", Role.STAFF, Instant.now());
            root = users.add("root", Role.ADMIN, Instant.now());
            assertTrue(users.revoke("carol", Instant.now()));
            assertFalse(users.revoke("carol", Instant.now()));
            IllegalArgumentException again = assertThrows(IllegalArgumentException.class, () -> users.add("carol", Role.STAFF, Instant.now()));
            assertTrue(again.getMessage().contains("there is a user 'carol' already"), again.getMessage());
            assertThrows(IllegalArgumentException.class, () -> users.add("Bad Name", Role.STAFF, Instant.now()));
            assertEquals(List.of("alice", "bob", "carol", "root"), users.list().stream().map(UserStore.User::name).toList());
        }
        s = ServiceFixture.start(db, "dry:1");
    }

    @AfterAll
    static void stop() {
        s.close();
    }

    @Test
    void secretsAreStoredHashedOnly() {
        String secret = alice.substring(alice.lastIndexOf('.') + 1);
        String stored = s.service.store().withConnection(c -> {
            try (var q = c.prepareStatement("SELECT secret_hash FROM app_user WHERE name = 'alice'"); var r = q.executeQuery()) {
                r.next();
                return r.getString(1);
            }
        });
        assertTrue(stored.startsWith("$2a$10$"), stored);
        assertFalse(stored.contains(secret));
    }

    @Test
    void aRevokedUserIs401() {
        ServiceFixture.Response r = s.get("/api/tasks", carol);
        assertEquals(401, r.status());
        assertEquals("the token is not valid", r.body().get("message").asText());
        // a wrong secret for a real name, too
        assertEquals(401, s.get("/api/tasks", "alice.not-the-secret").status());
    }

    @Test
    void staffIs403OnOperatorActions() {
        long id = s.submit("GoTo", "{\"dst\": \"ward2\"}");
        assertEquals(200, s.get("/api/tasks/" + id, bob).status());
        for (String path : new String[] { "/api/tasks/" + id + "/done", "/api/tasks/" + id + "/retry", "/api/robots/dry-1/offline" }) {
            ServiceFixture.Response r = s.post(path, "", bob);
            assertEquals(403, r.status(), path);
            assertEquals("this needs the operator role; bob is staff", r.body().get("message").asText());
        }
        assertEquals(403, s.get("/api/audit", bob).status());
        assertEquals(403, s.get("/api/users", alice).status());
    }

    @Test
    void theAuditLogNamesTheOperatorWhoCancelledAndFailedLogins() {
        // the robot out of dispatch, so that the task stays queued until it is cancelled
        assertEquals(200, s.post("/api/robots/dry-1/offline", "", alice).status());
        long id;
        try {
            id = s.submit("GoTo", "{\"dst\": \"ward1\"}");
            ServiceFixture.Response cancelled = s.delete("/api/tasks/" + id, alice);
            assertEquals(200, cancelled.status(), String.valueOf(cancelled.body()));
        } finally {
            assertEquals(200, s.post("/api/robots/dry-1/online", "", alice).status());
        }
        assertTrue(s.task(id).get("events").toString().contains("cancelled by alice (operator)"), s.task(id).toString());
        assertEquals(401, s.get("/api/robots", "mallory.guessed-secret").status());
        JsonNode audit = s.get("/api/audit", alice).body();
        assertTrue(contains(audit, "alice (operator)", "cancel", "task " + id), audit.toPrettyString());
        assertTrue(contains(audit, "alice (operator)", "robot-offline", "robot dry-1"), audit.toPrettyString());
        assertTrue(contains(audit, "mallory", "login-failed", "GET /api/robots from 127.0.0.1"), audit.toPrettyString());
        for (JsonNode e : audit) {
            assertFalse(e.toString().contains("guessed-secret"), "no presented secret is recorded: " + e);
        }
    }

    @Test
    void anAdminAddsAndRevokesUsersAndTheRevocationHoldsAtOnce() {
        ServiceFixture.Response added = s.post("/api/users", "{\"name\": \"dave\", \"role\": \"staff\"}", root);
        assertEquals(201, added.status(), String.valueOf(added.body()));
        String dave = added.body().get("token").asText();
        assertEquals(200, s.get("/api/tasks", dave).status());
        assertEquals(403, s.post("/api/users", "{\"name\": \"eve\", \"role\": \"admin\"}", dave).status());
        assertEquals(200, s.delete("/api/users/dave", root).status());
        assertEquals(401, s.get("/api/tasks", dave).status());
        JsonNode audit = s.get("/api/audit", root).body();
        assertTrue(contains(audit, "root (admin)", "user-add", "dave as staff"), audit.toPrettyString());
        assertTrue(contains(audit, "root (admin)", "user-revoke", "dave"), audit.toPrettyString());
    }

    private static boolean contains(JsonNode audit, String who, String what, String detail) {
        for (JsonNode e : audit) {
            if (e.get("who").asText().equals(who) && e.get("what").asText().equals(what) && e.get("detail").asText().startsWith(detail)) {
                return true;
            }
        }
        return false;
    }
}
