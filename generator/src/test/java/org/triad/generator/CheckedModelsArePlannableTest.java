package org.triad.generator;

import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;

import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.api.io.TempDir;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.dsl.triad.Situation;
import org.triad.planner.SolveResult;
import org.triad.planner.TriadEngine;
import org.triad.runtime.app.EnumValue;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.AppSchema;
import org.triad.runtime.schema.GoalSchema;
import org.triad.runtime.schema.Param;
import org.triad.runtime.schema.PddlTranslationException;
import org.triad.runtime.schema.PddlTranslator;
import org.triad.runtime.schema.TypeSchema;

/**
 * {@code ./triad check} accepting a model means it runs: every goal of every model without findings
 * (the example applications and every good rule case of the languages) translates to PDDL from each
 * of its situations, and for the rule cases the engine takes the translation (a plan, or "no plan", never an
 * input error).
 */
class CheckedModelsArePlannableTest {
	private static final Path RULES = Path.of("..", "dsl", "src", "test", "resources", "rules");

	@TempDir
	static Path tmp;

	@TestFactory
	Stream<DynamicTest> everyGoalOfEveryCheckedModelIsPlannable() throws IOException {
		List<DynamicTest> tests = new ArrayList<>();
		for (String app : List.of("hospital", "logistics")) {
			Path folder = Path.of("..", "models", app, "src", "main", "models");
			tests.add(DynamicTest.dynamicTest(app, () -> assertPlannable(folder, true)));
		}
		tests.add(DynamicTest.dynamicTest("lab", () -> assertPlannable(Path.of("src/test/resources/apps/lab"), true)));
		try (Stream<Path> codes = Files.list(RULES)) {
			for (Path code : codes.filter(Files::isDirectory).filter(p -> !p.endsWith("_base")).sorted().toList()) {
				try (Stream<Path> cases = Files.list(code)) {
					for (Path c : cases.filter(p -> p.getFileName().toString().startsWith("good")).sorted().toList()) {
						String name = code.getFileName() + "/" + c.getFileName();
						tests.add(DynamicTest.dynamicTest(name, () -> assertPlannable(materialize(c, name), false)));
					}
				}
			}
		}
		return tests.stream();
	}

	private static Path materialize(Path ruleCase, String name) throws IOException {
		Path dir = Files.createDirectories(tmp.resolve(name.replace('/', '_')));
		Path omit = ruleCase.resolve("omit");
		Set<String> omitted = Files.exists(omit) ? Set.copyOf(Files.readAllLines(omit).stream().map(String::trim).toList()) : Set.of();
		for (Path from : List.of(RULES.resolve("_base"), ruleCase)) {
			try (Stream<Path> files = Files.list(from)) {
				for (Path f : files.filter(Files::isRegularFile).toList()) {
					String n = f.getFileName().toString();
					if (!n.equals("omit") && !(from.endsWith("_base") && omitted.contains(n))) {
						Files.copy(f, dir.resolve(n), StandardCopyOption.REPLACE_EXISTING);
					}
				}
			}
		}
		return dir;
	}

	private static void assertPlannable(Path folder, boolean mustBeClean) {
		LoadedApplication app = ApplicationAssembler.load(folder);
		if (app.hasErrors()) {
			if (mustBeClean) {
				fail(app.diagnostics().toString());
			}
			return; // a good case of a rule may lean on a base the case itself changes; nothing to plan then
		}
		AppSchema schema = SchemaBuilder.build(app.application());
		List<State> states = new ArrayList<>();
		for (Situation s : app.application().getSituations()) {
			states.add(SituationReader.read(s, schema));
		}
		if (states.isEmpty()) {
			states.add(State.builder().build());
		}
		PddlTranslator translator = new PddlTranslator(schema);
		for (State state : states) {
			for (GoalSchema goal : schema.goals().values()) {
				Map<String, Object> binding = binding(goal, state, schema);
				if (binding == null) {
					continue;
				}
				try {
					PddlTranslator.Task task = translator.translate(state, goal, binding);
					if (mustBeClean) {
						continue; // the example applications' goals are planned by PlanningRoundTripTest and ThreeApplicationsPlanningTest
					}
					SolveResult result = new TriadEngine().solve(task.domain(), task.problem(), Duration.ofSeconds(20));
					assertNotEquals(SolveResult.Status.ERROR, result.status(), () -> goal.name() + ": " + result.message());
				} catch (PddlTranslationException e) {
					fail(folder + ": goal " + goal.name() + " passed the checks and cannot be translated: " + e.getMessage());
				}
			}
		}
	}

	/** Some value for each parameter: an object of the state of its type, a literal, or null if the state has none. */
	private static Map<String, Object> binding(GoalSchema goal, State state, AppSchema schema) {
		Map<String, Object> binding = new HashMap<>();
		for (Param p : goal.params()) {
			Object value = switch (p.type()) {
				case "int" -> 1;
				case "double" -> 1.5;
				case "String" -> "x";
				case "boolean" -> true;
				default -> {
					TypeSchema t = schema.types().get(p.type());
					if (t != null && t.isEnum()) {
						yield t.literals().isEmpty() ? null : new EnumValue(t.name(), t.literals().get(0));
					}
					yield state.objects().values().stream().filter(o -> schema.isSubtype(o.typeName(), p.type())).findFirst()
							.map(o -> (Object) o).orElse(null);
				}
			};
			if (value == null) {
				return null;
			}
			binding.put(p.name(), value);
		}
		return binding;
	}

}
