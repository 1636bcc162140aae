package org.triad.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The {@code ./triad} launcher, run as a user runs it, in a checkout of its own under a temporary
 * folder: the launcher script, and the built CLI's jars copied from this checkout. It chooses a JVM,
 * makes and reuses a start-up archive per JDK, makes it again when a jar is newer, and builds when a
 * source of the CLI changed (a stand-in {@code mvn} on the PATH records the build it is asked for).
 */
class LauncherTest {
	private static final Path CHECKOUT = Path.of("..").toAbsolutePath().normalize();

	@TempDir
	Path tmp;

	private Path home;
	private Path mvnLog;
	private Path bin;

	record Run(int exit, String out, String err) {
	}

	@BeforeEach
	void aCheckoutWithTheBuiltCli() throws IOException {
		home = tmp.resolve("triad");
		Path target = home.resolve("cli/target");
		Files.createDirectories(target);
		Path launcher = home.resolve("triad");
		Files.copy(CHECKOUT.resolve("triad"), launcher);
		assertTrue(launcher.toFile().setExecutable(true));
		Path builtCli = CHECKOUT.resolve("cli/target");
		try (Stream<Path> jars = Files.list(builtCli)) {
			for (Path jar : jars.filter(p -> p.getFileName().toString().matches("triad-cli-.*\\.jar")).toList()) {
				Files.copy(jar, target.resolve(jar.getFileName()));
			}
		}
		linkClassPath(builtCli.resolve("classpath.txt"), target.resolve("classpath.txt"));
		Path hospitalTarget = home.resolve("models/hospital/target");
		Files.createDirectories(hospitalTarget);
		linkClassPath(CHECKOUT.resolve("models/hospital/target/classpath.txt"), hospitalTarget.resolve("classpath.txt"));
		Path gripper = Path.of("planner/src/test/resources/pddl/ipc/gripper");
		Files.createDirectories(home.resolve(gripper));
		for (String file : List.of("domain.pddl", "prob01.pddl")) {
			Files.copy(CHECKOUT.resolve(gripper).resolve(file), home.resolve(gripper).resolve(file));
		}
		// built a minute ago, so that a source changed half a minute ago is newer, and older than the next build
		Files.writeString(target.resolve(".built"), "");
		Files.setLastModifiedTime(target.resolve(".built"), FileTime.from(Instant.now().minusSeconds(60)));
		bin = tmp.resolve("bin");
		Files.createDirectories(bin);
		mvnLog = tmp.resolve("mvn.log");
		Path mvn = bin.resolve("mvn");
		Files.writeString(mvn, "#!/bin/sh\necho \"$@\" >> '" + mvnLog + "'\n");
		assertTrue(mvn.toFile().setExecutable(true));
	}

	/** The class path file with every entry in the checkout copied to the same place in the new one. */
	private void linkClassPath(Path from, Path to) throws IOException {
		assertTrue(Files.isRegularFile(from), from + " (build the CLI and the hospital first)");
		List<String> entries = new ArrayList<>();
		for (String entry : Files.readString(from).trim().split(File.pathSeparator)) {
			Path p = Path.of(entry);
			if (p.startsWith(CHECKOUT)) {
				Path copy = home.resolve(CHECKOUT.relativize(p));
				Files.createDirectories(copy.getParent());
				if (!Files.exists(copy)) {
					Files.copy(p, copy);
				}
				entries.add(copy.toString());
			} else {
				entries.add(entry);
			}
		}
		Files.writeString(to, String.join(File.pathSeparator, entries));
	}

	private Run triad(Map<String, String> env, String... args) throws IOException, InterruptedException {
		List<String> command = new ArrayList<>(List.of("bash", home.resolve("triad").toString()));
		command.addAll(List.of(args));
		ProcessBuilder pb = new ProcessBuilder(command).directory(home.toFile());
		for (String v : List.of("TRIAD_JAVA", "TRIAD_NO_CDS", "TRIAD_JAVA_OPTS")) {
			pb.environment().remove(v);
		}
		pb.environment().put("PATH", bin + File.pathSeparator + System.getenv("PATH"));
		pb.environment().putAll(env);
		Process p = pb.start();
		p.getOutputStream().close();
		byte[] out = p.getInputStream().readAllBytes();
		byte[] err = p.getErrorStream().readAllBytes();
		assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the launcher exited");
		return new Run(p.exitValue(), new String(out, StandardCharsets.UTF_8), new String(err, StandardCharsets.UTF_8));
	}

	private Run solve(Map<String, String> env) throws IOException, InterruptedException {
		String gripper = "planner/src/test/resources/pddl/ipc/gripper/";
		Run run = triad(env, "solve", gripper + "domain.pddl", gripper + "prob01.pddl");
		assertEquals(0, run.exit(), run.err());
		// a plan, and as many actions as its cost line says
		long actions = run.out().lines().filter(l -> l.startsWith("(")).count();
		assertTrue(actions >= 11 && run.out().endsWith("; cost = " + actions + " (unit cost)\n"), run.out());
		return run;
	}

	private List<Path> archives() throws IOException {
		Path dir = home.resolve("cli/target/startup");
		if (!Files.isDirectory(dir)) {
			return List.of();
		}
		try (Stream<Path> files = Files.list(dir)) {
			return files.sorted().toList();
		}
	}

	/** The archive the launcher makes for {@code solve} on the JDK whose home is the given one. */
	private Path solveArchive(Path javaHome) throws IOException {
		String release = Files.readString(javaHome.resolve("release"));
		int feature = Integer.parseInt(release.replaceAll("(?s).*JAVA_VERSION=\"(\\d+).*", "$1"));
		return home.resolve("cli/target/startup/solve-" + javaHome.getFileName() + "-" + feature + (feature >= 25 ? ".aot" : ".jsa"));
	}

	@Test
	void theTestsJdkAndTheJdkTheLauncherChoosesPrintTheSamePlan() throws IOException, InterruptedException {
		Path javaHome = Path.of(System.getProperty("java.home")).toRealPath();
		Run chosen = solve(Map.of());
		Run explicit = solve(Map.of("TRIAD_JAVA", javaHome.toString()));
		assertEquals(chosen.out(), explicit.out());
		assertTrue(archives().contains(solveArchive(javaHome)), archives().toString());
		assertEquals(chosen.out(), solve(Map.of("TRIAD_JAVA", javaHome.resolve("bin/java").toString())).out());
		assertEquals(chosen.out(), solve(Map.of("TRIAD_NO_CDS", "1")).out());
		assertFalse(Files.exists(mvnLog), "nothing to build");
	}

	@Test
	void anArchiveIsReusedAndMadeAgainWhenAJarIsNewer() throws IOException, InterruptedException {
		Path javaHome = Path.of(System.getProperty("java.home")).toRealPath();
		Map<String, String> java = Map.of("TRIAD_JAVA", javaHome.toString());
		solve(java);
		Path archive = solveArchive(javaHome);
		FileTime made = Files.getLastModifiedTime(archive);
		solve(java);
		assertEquals(made, Files.getLastModifiedTime(archive), "reused");
		FileTime old = FileTime.from(Instant.parse("2001-01-01T00:00:00Z"));
		Files.setLastModifiedTime(archive, old);
		solve(java);
		assertTrue(Files.getLastModifiedTime(archive).compareTo(old) > 0, "made again: " + Files.getLastModifiedTime(archive));
	}

	@Test
	void aChangedSourceOfTheCliIsBuiltATestSourceIsNot() throws IOException, InterruptedException {
		Map<String, String> noArchive = Map.of("TRIAD_NO_CDS", "1");
		FileTime later = FileTime.from(Instant.now().minusSeconds(30));
		Path test = home.resolve("planner/src/test/java/T.java");
		Files.createDirectories(test.getParent());
		Files.writeString(test, "class T {}");
		Files.setLastModifiedTime(test, later);
		solve(noArchive);
		assertFalse(Files.exists(mvnLog), "a test source is not built for the CLI");

		for (String source : List.of("planner/src/main/java/M.java", "cli/src/main/java/M.java", "pom.xml")) {
			Files.setLastModifiedTime(home.resolve("cli/target/.built"), FileTime.from(Instant.now().minusSeconds(60)));
			Path main = home.resolve(source);
			Files.createDirectories(main.getParent());
			Files.writeString(main, "changed");
			Files.setLastModifiedTime(main, later);
			Run run = solve(noArchive);
			assertTrue(run.err().startsWith("triad: building"), source + ": " + run.err());
			List<String> builds = Files.readAllLines(mvnLog);
			assertEquals(1, builds.size(), source + ": " + builds);
			assertTrue(builds.get(0).contains("-pl cli,models/hospital -am install"), builds.get(0));
			Files.delete(mvnLog);
			solve(noArchive);
			assertFalse(Files.exists(mvnLog), source + ": built once");
		}
	}

	@Test
	void aTriadJavaThatIsNoJavaIsAClearError() throws IOException, InterruptedException {
		Path nowhere = tmp.resolve("no-jdk");
		Run run = triad(Map.of("TRIAD_JAVA", nowhere.toString()), "--help");
		assertEquals(2, run.exit());
		assertEquals("triad: TRIAD_JAVA=" + nowhere + " is neither a JDK (with bin/java) nor a java executable\n", run.err());
		assertEquals("", run.out());
	}

	@Test
	void otherCommandsRunOnTheWholeClassPath() throws IOException, InterruptedException {
		Run help = triad(Map.of("TRIAD_NO_CDS", "1"), "--help");
		assertEquals(0, help.exit(), help.err());
		assertTrue(help.out().startsWith("Usage: triad"), help.out());
		Run solveHelp = triad(Map.of("TRIAD_NO_CDS", "1"), "solve", "--help");
		assertEquals(0, solveHelp.exit(), solveHelp.err());
		assertTrue(solveHelp.out().startsWith("Usage: triad solve"), solveHelp.out());
		assertEquals(List.of(), archives().stream().map(Path::toString).collect(Collectors.toList()), "TRIAD_NO_CDS makes no archive");
	}
}
