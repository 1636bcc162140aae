package org.triad.service;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** What the service says when it cannot start: one line naming the problem, no stack trace. */
class StartupErrorsTest {
    @TempDir
    Path dir;

    private ServiceError failure(TriadService.Options o) {
        ServiceError e = assertThrows(ServiceError.class, () -> TriadService.start(o).close());
        assertFalse(e.getMessage().contains("\n\tat "), e.getMessage());
        return e;
    }

    private TriadService.Options with(List<String> robots, Path db) {
        return new TriadService.Options(ServiceFixture.HOSPITAL, robots, null, db, null, "127.0.0.1", 0,
                Map.of(AccessTokens.SUBMIT_ENV, ServiceFixture.SUBMIT, AccessTokens.OPERATOR_ENV, ServiceFixture.OPERATOR));
    }

    @Test
    void robotsThatDoNotExistOrAreMistypedAreNamed() {
        String unknown = failure(with(List.of("warp:3"), dir.resolve("a"))).getMessage();
        assertTrue(unknown.contains("unknown robot scheme 'warp'") && unknown.contains("dry:N"), unknown);
        String bad = failure(with(List.of("dry:many"), dir.resolve("b"))).getMessage();
        assertTrue(bad.contains("--robots dry:many: dry:N takes a whole number, not 'many'"), bad);
        String action = failure(with(List.of("dry:1,fail=fly*2"), dir.resolve("c"))).getMessage();
        assertTrue(action.contains("no action 'fly'"), action);
        String situation = failure(with(List.of("dry:1,state=Noon"), dir.resolve("d"))).getMessage();
        assertTrue(situation.contains("no situation 'Noon'") && situation.contains("Morning"), situation);
        String form = failure(with(List.of("three robots"), dir.resolve("e"))).getMessage();
        assertTrue(form.contains("SCHEME:ARGUMENT"), form);
    }

    @Test
    void aDatabaseThatIsNotOneOrCannotBeCreatedIsAStartupError() throws Exception {
        Path garbage = dir.resolve("garbage.mv.db");
        Files.writeString(garbage, "this is not an H2 database ".repeat(200));
        String damaged = failure(with(List.of("dry:1"), garbage)).getMessage();
        assertTrue(damaged.startsWith("database " + garbage), damaged);
        String missing = failure(with(List.of("dry:1"), dir.resolve("no/such/folder/db"))).getMessage();
        assertTrue(missing.contains("does not exist"), missing);
    }

    @Test
    void aPortInUseIsAStartupError() {
        try (TriadService first = TriadService.start(with(List.of("dry:1"), dir.resolve("one")))) {
            TriadService.Options same = new TriadService.Options(ServiceFixture.HOSPITAL, List.of("dry:1"), null, dir.resolve("two"), null,
                    "127.0.0.1", first.port(), Map.of());
            String m = failure(same).getMessage();
            assertTrue(m.contains("cannot listen on 127.0.0.1:" + first.port()), m);
        }
    }

    @Test
    void modelsThatDoNotExistAreAStartupError() {
        TriadService.Options o = new TriadService.Options(dir.resolve("nowhere"), List.of(), null, (String) null, null, "127.0.0.1", 0, Map.of());
        assertTrue(failure(o).getMessage().startsWith("not a folder: "));
    }
}
