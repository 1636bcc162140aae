package org.triad.generator;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.planner.PlanValidator;
import org.triad.planner.SolveResult;
import org.triad.planner.TriadEngine;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.AppSchema;
import org.triad.runtime.schema.GoalSolver;

/**
 * Benchmark (not a test): how long the Planner component needs per hospital goal, from the current
 * state to a plan of the application's actions (translation to the planner's typed PDDL model,
 * grounding, search), warm, median of 200 runs, in wall-clock and in CPU time of the planning thread
 * (CPU time is what to compare on a machine shared with builds). The last row is the battery-draining
 * delivery's PDDL (the fixture {@code models/hospital/src/test/resources/pddl/delivered-gauze-*.pddl}, the
 * courier's battery drained per metre) solved by the engine directly. Run from the repository root (after {@code ./triad --help} has built the tool):
 * {@code mvn -q -pl generator -am test-compile && java -cp "generator/target/test-classes:generator/target/classes:$(cat cli/target/classpath.txt)" org.triad.generator.HospitalPlanningBenchmark}
 */
public final class HospitalPlanningBenchmark {
	private HospitalPlanningBenchmark() {
	}

	private static State situation(LoadedApplication app, AppSchema schema, String name) {
		return SituationReader.read(app.application().getSituations().stream().filter(s -> s.getName().equals(name)).findFirst().orElseThrow(),
				schema);
	}

	public static void main(String[] args) throws java.io.IOException {
		Path models = Path.of(args.length > 0 ? args[0] : "models/hospital/src/main/models");
		LoadedApplication app = ApplicationAssembler.load(models);
		if (app.hasErrors()) {
			throw new IllegalStateException("hospital models have errors: " + app.diagnostics());
		}
		AppSchema schema = SchemaBuilder.build(app.application());
		State morning = situation(app, schema, "Morning");
		State evening = situation(app, schema, "Evening");
		// the last from Evening, whose courier (25 %) must charge on the way: the row where the battery binds
		String[][] goals = { { "IsAt", "ward3" }, { "Holds", "gauze" }, { "Delivered", "gauze", "ward1" }, { "PersonAt", "alice", "xray" },
				{ "FollowedTo", "bob", "ward3" }, { "Evening: Delivered", "gauze", "ward1" } };
		GoalSolver planner = new GoalSolver(schema);
		ThreadMXBean threads = ManagementFactory.getThreadMXBean();
		System.out.println("| goal | plan length | median ms | p90 ms | median CPU ms |");
		System.out.println("|---|---|---|---|---|");
		for (String[] row : goals) {
			String[] g = row.clone();
			State from = morning;
			if (g[0].startsWith("Evening: ")) {
				g[0] = g[0].substring("Evening: ".length());
				from = evening;
			}
			List<Object> goalArgs = new ArrayList<>();
			for (int i = 1; i < g.length; i++) {
				goalArgs.add(from.object(g[i]).orElseThrow());
			}
			int length = -1;
			for (int i = 0; i < 50; i++) {
				length = planner.plan(g[0], goalArgs, from).plan().size();
			}
			double[] ms = new double[200];
			double[] cpu = new double[ms.length];
			for (int i = 0; i < ms.length; i++) {
				long c0 = threads.getCurrentThreadCpuTime();
				long t0 = System.nanoTime();
				planner.plan(g[0], goalArgs, from);
				ms[i] = (System.nanoTime() - t0) / 1e6;
				cpu[i] = (threads.getCurrentThreadCpuTime() - c0) / 1e6;
			}
			Arrays.sort(ms);
			Arrays.sort(cpu);
			System.out.printf(Locale.ROOT, "| %s(%s) | %d | %.2f | %.2f | %.3f |%n", row[0], String.join(", ", Arrays.copyOfRange(g, 1, g.length)),
					length, ms[ms.length / 2], ms[(int) (ms.length * 0.9)], cpu[cpu.length / 2]);
		}
		Path pddl = Path.of("models/hospital/src/test/resources/pddl");
		Domain domain = PddlParser.parseDomain(pddl.resolve("delivered-gauze-domain.pddl"));
		Problem problem = PddlParser.parseProblem(pddl.resolve("delivered-gauze-problem.pddl"));
		TriadEngine engine = new TriadEngine();
		SolveResult r = null;
		for (int i = 0; i < 50; i++) {
			r = engine.solve(domain, problem, Duration.ofSeconds(60));
		}
		double[] ms = new double[200];
		double[] cpu = new double[ms.length];
		for (int i = 0; i < ms.length; i++) {
			long c0 = threads.getCurrentThreadCpuTime();
			long t0 = System.nanoTime();
			engine.solve(domain, problem, Duration.ofSeconds(60));
			ms[i] = (System.nanoTime() - t0) / 1e6;
			cpu[i] = (threads.getCurrentThreadCpuTime() - c0) / 1e6;
		}
		Arrays.sort(ms);
		Arrays.sort(cpu);
		System.out.printf(Locale.ROOT, "| Delivered(gauze, ward1), battery PDDL, %s m | %d | %.2f | %.2f | %.3f |%n",
				r.isSolved() ? String.format(Locale.ROOT, "%.1f", PlanValidator.metricValue(domain, problem, r.plan()).orElse(Double.NaN)) : r.status(),
				r.isSolved() ? r.plan().length() : -1, ms[ms.length / 2], ms[(int) (ms.length * 0.9)], cpu[cpu.length / 2]);
	}
}
