package org.triad.dsl.arc;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;

/** .arc files sit next to an application's other models: loaded and checked with them, without disturbing them. */
class ArcInApplicationTest {
	@TempDir
	Path app;

	@Test
	void architectureNextToApplicationModels() throws Exception {
		copy(Path.of("..", "models", "hospital", "src", "main", "models"), app);
		copy(Path.of("..", "refarc", "src", "main", "arc"), app.resolve("arc"));
		Files.writeString(app.resolve("arc/HospitalApp.arc"), """
				package app;
				import org.triad.runtime.app.TaskInstance;
				import org.triad.refarc.*;
				component HospitalApp(StateSource s, GoalPlanner g, ActionRunner a) {
				  port in TaskInstance request;
				  port out Status status;
				  RefArc core(s, g, a);
				  RemoteOperator operator;
				  request -> core.task;
				  core.status -> status, operator.status;
				}
				""");
		LoadedApplication loaded = ApplicationAssembler.load(app);
		assertEquals("", loaded.diagnostics().stream().map(d -> d.format(loaded.root())).collect(Collectors.joining("\n")));

		Files.writeString(app.resolve("arc/HospitalApp.arc"), Files.readString(app.resolve("arc/HospitalApp.arc"))
				.replace("core.status -> status, operator.status;", "core.status -> status, operator.status, faults;"));
		LoadedApplication bad = ApplicationAssembler.load(app);
		// the runtime feeds 'faults'; nothing may send to it, least of all a Status
		assertEquals(List.of("arc/HospitalApp.arc:10:43: error arc.direction-mismatch", "arc/HospitalApp.arc:10:43: error arc.type-mismatch"),
				bad.diagnostics().stream().map(d -> d.format(bad.root())).map(s -> s.substring(0, s.indexOf(':', s.indexOf("error"))))
						.sorted().toList());
	}

	private static void copy(Path from, Path to) throws Exception {
		try (Stream<Path> walk = Files.walk(from)) {
			for (Path p : walk.filter(Files::isRegularFile).toList()) {
				Path target = to.resolve(from.relativize(p).toString());
				Files.createDirectories(target.getParent());
				Files.copy(p, target);
			}
		}
	}
}
