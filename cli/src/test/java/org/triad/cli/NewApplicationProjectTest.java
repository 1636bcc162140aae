package org.triad.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code ./triad new} (Triad's archetype) makes a project outside the repository that builds and passes
 * its test with {@code mvn verify}: run in a child Maven, in an empty folder, against a local repository of
 * its own holding this reactor's Triad artifacts (as `mvn install` would put them), third-party artifacts
 * coming from the repository this build uses (and Maven Central for anything it lacks).
 */
class NewApplicationProjectTest {
	private static final Path REACTOR = Path.of("..").toAbsolutePath().normalize();
	private static final String VERSION = ArchetypeProject.TRIAD_VERSION;
	/** Triad's artifacts a new project needs, directly or transitively: folder and artifactId. */
	private static final List<String[]> ARTIFACTS = List.of(new String[] { "planner", "triad-planner" },
			new String[] { "runtime", "triad-runtime" }, new String[] { "dsl", "triad-dsl" }, new String[] { "generator", "triad-generator" },
			new String[] { "refarc", "triad-refarc" });

	@Test
	void aNewProjectBuildsAndItsTaskRunsThroughRefArc(@TempDir Path tmp) throws Exception {
		Path project = tmp.resolve("work").resolve("pharmacy");
		StringWriter out = new StringWriter();
		StringWriter err = new StringWriter();
		int code = TriadCli.execute(new String[] { "new", project.toString(), "--name", "Pharmacy" }, new PrintWriter(out, true),
				new PrintWriter(err, true));
		assertEquals(0, code, err.toString());
		assertTrue(out.toString().startsWith("created application Pharmacy in " + project), out.toString());
		assertTrue(Files.isRegularFile(project.resolve("src/main/models/Pharmacy.cd")));
		assertTrue(Files.isRegularFile(project.resolve("src/test/java/com/example/pharmacy/RestockTest.java")));
		assertTrue(Files.readString(project.resolve("pom.xml")).contains("<artifactId>pharmacy</artifactId>"));

		Path repo = tmp.resolve("m2");
		installReactorArtifacts(repo);
		Path settings = tmp.resolve("settings.xml");
		Files.writeString(settings, settings(repo, Path.of(System.getProperty("triad.maven.repo"))));
		Path log = tmp.resolve("mvn.log");
		Process mvn = new ProcessBuilder("mvn", "-B", "-s", settings.toString(), "verify").directory(project.toFile())
				.redirectErrorStream(true).redirectOutput(log.toFile()).start();
		try {
			assertTrue(mvn.waitFor(10, TimeUnit.MINUTES), "mvn verify of the new project did not end within 10 minutes");
		} finally {
			mvn.destroyForcibly();
		}
		String output = Files.readString(log, StandardCharsets.UTF_8);
		assertEquals(0, mvn.exitValue(), output);
		assertTrue(output.contains("Tests run: 2, Failures: 0, Errors: 0, Skipped: 0"), output);
		assertTrue(Files.isRegularFile(project.resolve("target/generated-sources/triad/generated/pharmacy/PharmacyRefArc.java")));
	}

	@Test
	void aFolderThatIsNotEmptyOrABadNameIsRefused(@TempDir Path tmp) throws IOException {
		Files.writeString(tmp.resolve("notes.txt"), "mine");
		StringWriter err = new StringWriter();
		assertEquals(2, TriadCli.execute(new String[] { "new", tmp.toString(), "--name", "Pharmacy" }, new PrintWriter(new StringWriter()),
				new PrintWriter(err, true)));
		assertEquals("triad new: " + tmp + " exists and is not an empty folder; name a new one", err.toString().trim());
		err.getBuffer().setLength(0);
		assertEquals(2, TriadCli.execute(new String[] { "new", tmp.resolve("x").toString(), "--name", "pharmacy" },
				new PrintWriter(new StringWriter()), new PrintWriter(err, true)));
		assertTrue(err.toString().contains("--name takes a name that starts with a capital letter"), err.toString());
		assertTrue(Files.notExists(tmp.resolve("x")));
	}

	/** Lays out this reactor's built jars and poms as 'mvn install' would in {@code repo}. */
	private static void installReactorArtifacts(Path repo) throws IOException {
		copy(REACTOR.resolve("pom.xml"), repo, "triad-parent", "pom");
		for (String[] a : ARTIFACTS) {
			Path jar = REACTOR.resolve(a[0]).resolve("target").resolve(a[1] + "-" + VERSION + ".jar");
			assertTrue(Files.isRegularFile(jar), jar + " is missing: build the reactor first (mvn -B verify)");
			copy(jar, repo, a[1], "jar");
			copy(REACTOR.resolve(a[0]).resolve("pom.xml"), repo, a[1], "pom");
		}
	}

	private static void copy(Path file, Path repo, String artifactId, String extension) throws IOException {
		Path dir = repo.resolve("org/triad").resolve(artifactId).resolve(VERSION);
		Files.createDirectories(dir);
		Files.copy(file, dir.resolve(artifactId + "-" + VERSION + "." + extension), StandardCopyOption.REPLACE_EXISTING);
	}

	private static String settings(Path localRepo, Path buildRepo) {
		String repositories = """
				<repository><id>build-repository</id><url>%s</url></repository>
				<repository><id>central</id><url>https://repo.maven.apache.org/maven2</url></repository>
				""".formatted(buildRepo.toUri());
		return """
				<settings>
				  <localRepository>%s</localRepository>
				  <profiles><profile><id>repos</id>
				    <repositories>%s</repositories>
				    <pluginRepositories>%s</pluginRepositories>
				  </profile></profiles>
				  <activeProfiles><activeProfile>repos</activeProfile></activeProfiles>
				</settings>
				""".formatted(localRepo, repositories, repositories.replace("repository>", "pluginRepository>"));
	}
}
