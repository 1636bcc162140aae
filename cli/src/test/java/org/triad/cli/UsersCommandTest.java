package org.triad.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.service.auth.UserStore;
import org.triad.service.store.TaskStore;

/** {@code triad users}: add, list and revoke on a service database, new or left by an earlier start. */
class UsersCommandTest {
	private record Run(int exit, String out, String err) {
	}

	private static Run triad(String... args) {
		StringWriter out = new StringWriter();
		StringWriter err = new StringWriter();
		int exit = TriadCli.execute(args, new PrintWriter(out, true), new PrintWriter(err, true));
		return new Run(exit, out.toString(), err.toString());
	}

	@Test
	void addListRevoke(@TempDir Path dir) {
		String db = dir.resolve("service").toString();
		Run added = triad("users", dir.toString(), "add", "alice", "--role", "operator", "--db", db);
		assertEquals(0, added.exit(), added.err());
		assertTrue(added.out().startsWith("user alice (operator) added; the token, shown only now: alice."), added.out());
		String token = added.out().strip().substring(added.out().strip().lastIndexOf(' ') + 1);
		try (TaskStore store = TaskStore.open(Path.of(db))) {
			assertEquals("alice", new UserStore(store).authenticate(token).orElseThrow().name());
		}
		Run list = triad("users", dir.toString(), "list", "--db", db);
		assertEquals(0, list.exit(), list.err());
		List<String> lines = list.out().strip().lines().toList();
		assertEquals(1, lines.size(), list.out());
		assertTrue(lines.get(0).startsWith("alice\toperator\tadded "), list.out());
		assertEquals(0, triad("users", dir.toString(), "revoke", "alice", "--db", db).exit());
		assertTrue(triad("users", dir.toString(), "list", "--db", db).out().contains("\trevoked "));
		try (TaskStore store = TaskStore.open(Path.of(db))) {
			assertTrue(new UserStore(store).authenticate(token).isEmpty(), "a revoked token is refused");
		}
		Run again = triad("users", dir.toString(), "revoke", "alice", "--db", db);
		assertEquals(2, again.exit());
		assertEquals("triad users: no user 'alice' to revoke (unknown or revoked already)", again.err().strip());
		Run role = triad("users", dir.toString(), "add", "bob", "--role", "boss", "--db", db);
		assertEquals(2, role.exit());
		assertEquals("triad users: a role is staff, operator or admin, not 'boss'", role.err().strip());
	}
}
