package org.triad.tests.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.cli.TriadCli;

/** {@code triad serve} when it cannot start: one line on stderr, exit code 2 (the running service is tested in service/ and tests/). */
class ServeCommandTest {
	record Run(int exit, String out, String err) {
	}

	static Run run(String... args) {
		StringWriter out = new StringWriter();
		StringWriter err = new StringWriter();
		int exit = TriadCli.execute(args, new PrintWriter(out, true), new PrintWriter(err, true));
		return new Run(exit, out.toString(), err.toString());
	}

	@Test
	void aMissingModelsFolderIsOneLineAndExitCode2(@TempDir Path dir) {
		Run run = run("serve", dir.resolve("nowhere").toString(), "--port", "0");
		assertEquals(2, run.exit());
		assertEquals("triad serve: not a folder: " + dir.resolve("nowhere"), run.err().strip());
	}

	@Test
	void anUnknownRobotSchemeIsOneLineAndExitCode2(@TempDir Path dir) {
		Run run = run("serve", Path.of("..", "models", "hospital").toString(), "--robots", "warp:2", "--port", "0",
				"--db", dir.resolve("db").toString());
		assertEquals(2, run.exit());
		assertTrue(run.err().startsWith("triad serve: unknown robot scheme 'warp'; for Hospital: sim:N"), run.err());
		// the error, then how to get access whatever this failed start left in the database (issue 25)
		List<String> lines = run.err().strip().lines().toList();
		assertEquals(2, lines.size(), run.err());
		assertTrue(lines.get(1).startsWith("  access, whatever this start left: ./triad users "), run.err());
	}

	@Test
	void aDamagedDatabaseIsRefusedNamingTheRecoveryCommand(@TempDir Path dir) throws Exception {
		java.nio.file.Files.writeString(dir.resolve("db.db"), "not a database ".repeat(500));
		Run run = run("serve", Path.of("..", "models", "hospital").toString(), "--robots", "dry:1", "--port", "0", "--db", dir.resolve("db").toString());
		assertEquals(2, run.exit());
		assertTrue(run.err().startsWith("triad serve: database " + dir.resolve("db.db") + " is damaged: not a SQLite database"), run.err());
		assertTrue(run.err().contains("--db " + dir.resolve("db.db") + " --recover"), run.err());
		Run onServer = run("serve", Path.of("..", "models", "hospital").toString(), "--db", "postgresql://triad@127.0.0.1:1/triad", "--recover");
		assertEquals(2, onServer.exit());
		assertTrue(onServer.err().contains("--recover salvages the embedded database file"), onServer.err());
	}

	@Test
	void aBadPortIsExitCode2() {
		assertEquals(2, run("serve", ".", "--port", "70000").exit());
	}
}
