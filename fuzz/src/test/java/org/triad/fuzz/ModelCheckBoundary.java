package org.triad.fuzz;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.dsl.app.ModelDiagnostic;
import org.triad.dsl.validation.ActorIssueCodes;
import org.triad.dsl.validation.ArcIssueCodes;
import org.triad.dsl.validation.CdIssueCodes;
import org.triad.dsl.validation.CommonIssueCodes;
import org.triad.dsl.validation.GoalIssueCodes;
import org.triad.dsl.validation.StateIssueCodes;
import org.triad.dsl.validation.TaskIssueCodes;

/**
 * The promise of {@code ./triad check} (its entry, {@link ApplicationAssembler#load}), checked for one
 * model file with arbitrary content in an otherwise valid application (the paper's logistics
 * example): the check returns within a bound, and every finding has a registered code and a place
 * inside the files; an internal failure that the loader turned into a finding ("cannot read the
 * file", "cannot check the file") breaks the promise as much as an exception does.
 */
final class ModelCheckBoundary {
	/** Far above what any input of the corpus takes; only a hang or an explosion gets near it. */
	static final long BOUND_MS = 30_000;

	static final List<String> BASE = List.of("LogisticsDomain.cd", "LogisticsRobot.actor", "RoomsWorld.actor", "IsAt.goal",
			"GoTo.task", "Floor.state");

	/** The paper's logistics application, as the example project has it. */
	static final Path LOGISTICS = Path.of("..", "models", "logistics", "src", "main", "models");

	private static final Set<String> CODES = registeredCodes();
	private static Path app;

	private ModelCheckBoundary() {
	}

	/** Replaces (or adds) {@code fileName} in the application with {@code content} and checks the application. */
	static synchronized void check(String fileName, byte[] content) throws IOException {
		Path dir = application();
		for (String base : BASE) {
			Files.copy(resource(base), dir.resolve(base), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
		}
		Path file = dir.resolve(fileName);
		Files.write(file, content);
		try {
			long start = System.nanoTime();
			LoadedApplication loaded = ApplicationAssembler.load(dir);
			long ms = (System.nanoTime() - start) / 1_000_000;
			assertTrue(ms < BOUND_MS, "checking took " + ms + " ms");
			for (ModelDiagnostic d : loaded.diagnostics()) {
				assertKept(d, dir, file, content);
			}
		} finally {
			if (!BASE.contains(fileName)) {
				Files.deleteIfExists(file);
			}
		}
	}

	private static void assertKept(ModelDiagnostic d, Path dir, Path file, byte[] content) {
		String shown = d.format(dir);
		if (!CODES.contains(d.code())) {
			fail("a finding without a registered code: " + shown);
		}
		if (d.message().startsWith("cannot read the file") || d.message().startsWith("cannot check the file")) {
			fail("an internal failure reported as a finding: " + shown);
		}
		if (!d.file().startsWith(dir) || d.line() < 1 || d.column() < 1) {
			fail("a finding outside the files: " + shown);
		}
		int lines = 1;
		for (byte b : content) {
			if (b == '\n' || b == '\r') {
				lines++; // \r\n counts twice: a bound, not an exact count
			}
		}
		if (d.file().equals(file) && d.line() > lines) {
			fail("a finding past the end of the file (" + lines + " lines): " + shown);
		}
	}

	private static Path application() throws IOException {
		if (app == null) {
			app = Files.createTempDirectory("triad-fuzz-app-");
			app.toFile().deleteOnExit();
		}
		return app;
	}

	private static Path resource(String name) {
		return LOGISTICS.resolve(name);
	}

	private static Set<String> registeredCodes() {
		Set<String> codes = new HashSet<>();
		for (Class<?> registry : List.of(CommonIssueCodes.class, CdIssueCodes.class, ActorIssueCodes.class, GoalIssueCodes.class,
				TaskIssueCodes.class, StateIssueCodes.class, ArcIssueCodes.class)) {
			for (Field f : registry.getFields()) {
				if (Modifier.isStatic(f.getModifiers()) && f.getType() == String.class) {
					try {
						codes.add((String) f.get(null));
					} catch (IllegalAccessException e) {
						throw new IllegalStateException(e);
					}
				}
			}
		}
		return codes;
	}
}
