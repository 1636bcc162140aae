package org.triad.dsl;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.function.IntFunction;
import java.util.stream.Stream;

import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;

/**
 * How the time of {@code ./triad check} (its entry, {@link ApplicationAssembler#load}) grows with deep
 * and large models: conjunctions of n terms (up to the depth limit and past it), n nested
 * parentheses, and files of n kilobytes of goals, each next to the small application of the rule
 * tests. One JVM; per size one warm-up and 5 timed loads (CPU time of the loading thread); prints
 * the median and, over the series' n=1 row, the time each further unit of input adds, whose
 * flatness is what "linear" means here.
 * <p>
 * Run from the repository root (see FUZZING.md for the command).
 */
public final class DeepModelsBenchmark {
	private static final String CALL = "Bot.holds(b)";
	private static final int RUNS = 5;
	/** Loading runs on the calling thread; its CPU time is what a shared machine does not distort. */
	private static final ThreadMXBean CPU = ManagementFactory.getThreadMXBean();

	private DeepModelsBenchmark() {
	}

	public static void main(String[] args) throws IOException {
		Path base = Path.of(args.length > 0 ? args[0] : "dsl/src/test/resources/rules/_base");
		System.out.println("| input | n | findings | median CPU ms | (median - n=1) CPU us per unit |");
		System.out.println("|---|---|---|---|---|");
		for (int n : new int[] { 1, 100, 300, 1_000, 3_000, 10_000 }) {
			measure(base, "conjunction of n terms", n, k -> goal(String.join(" && ", Collections.nCopies(k, CALL))));
		}
		for (int n : new int[] { 1, 10, 30, 99, 1_000, 10_000 }) {
			measure(base, "n nested parentheses", n, k -> goal("(".repeat(k) + CALL + ")".repeat(k)));
		}
		for (int n : new int[] { 1, 250, 500, 1_000, 2_000 }) {
			measure(base, "n KB of goals", n, DeepModelsBenchmark::goalsOfKilobytes);
		}
	}

	private static double baseline;

	private static void measure(Path base, String what, int n, IntFunction<String> atGoal) throws IOException {
		Path dir = Files.createTempDirectory("triad-bench-");
		try (Stream<Path> files = Files.list(base)) {
			for (Path f : files.toList()) {
				Files.copy(f, dir.resolve(f.getFileName()));
			}
		}
		Files.writeString(dir.resolve("At.goal"), atGoal.apply(n));
		LoadedApplication app = ApplicationAssembler.load(dir); // warm-up
		List<Long> nanos = new ArrayList<>();
		for (int i = 0; i < RUNS; i++) {
			long start = CPU.getCurrentThreadCpuTime();
			app = ApplicationAssembler.load(dir);
			nanos.add(CPU.getCurrentThreadCpuTime() - start);
		}
		Collections.sort(nanos);
		double ms = nanos.get(RUNS / 2) / 1e6;
		String codes = app.diagnostics().isEmpty() ? "none" : app.diagnostics().get(0).code() + " x" + app.diagnostics().size();
		if (n == 1) {
			baseline = ms;
		}
		String perUnit = n == 1 ? "" : String.format(Locale.ROOT, "%.1f", (ms - baseline) * 1000 / (n - 1));
		System.out.printf(Locale.ROOT, "| %s | %d | %s | %.1f | %s |%n", what, n, codes, ms, perUnit);
		try (Stream<Path> files = Files.list(dir)) {
			for (Path f : files.toList()) {
				Files.delete(f);
			}
		}
		Files.delete(dir);
	}

	private static String goal(String condition) {
		return "domain Shop;\n\ngoal At(Place p) {\n  Bot.loc() == p\n}\n\ngoal Holding(Box b) {\n  " + condition + "\n}\n";
	}

	private static String goalsOfKilobytes(int kilobytes) {
		StringBuilder b = new StringBuilder(goal(CALL));
		for (int i = 0; b.length() < kilobytes * 1024; i++) {
			b.append("\ngoal Reach").append(i).append("(Place p, Box b) {\n  Bot.loc() == p && (Bot.holds(b) || !World.adj(p, p))\n}\n");
		}
		return b.toString();
	}
}
