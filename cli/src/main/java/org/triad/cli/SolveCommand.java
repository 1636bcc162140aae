package org.triad.cli;

import java.util.List;
import java.util.concurrent.Callable;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Unmatched;

/** {@code triad solve DOMAIN PROBLEM [-o PLAN]}: Triad's planning engine on its own. */
@Command(name = "solve", mixinStandardHelpOptions = false,
		description = { "Solve a PDDL problem with Triad's planning engine and print the plan as VAL reads it.",
				"Usage: triad solve DOMAIN.pddl PROBLEM.pddl [-o PLAN] [--planner triad|pddl4j] [--timeout SECONDS]",
				"Exit code: 0 solved, 1 no plan, 2 bad input." })
public final class SolveCommand implements Callable<Integer> {
	@Parameters(paramLabel = "ARGS", arity = "0..*", description = "DOMAIN.pddl PROBLEM.pddl and options")
	private List<String> args = List.of();

	@Unmatched
	private List<String> options = List.of();

	@CommandLine.Spec
	private CommandLine.Model.CommandSpec spec;

	@Override
	public Integer call() {
		List<String> all = new java.util.ArrayList<>(args);
		all.addAll(options);
		java.io.PrintStream out = new java.io.PrintStream(new WriterStream(spec.commandLine().getOut()), true);
		java.io.PrintStream err = new java.io.PrintStream(new WriterStream(spec.commandLine().getErr()), true);
		return org.triad.runtime.planning.SolveCommand.run(all, out, err);
	}

	/** Bridges picocli's writers to the PrintStreams the engine's command writes to. */
	private static final class WriterStream extends java.io.OutputStream {
		private final java.io.PrintWriter writer;

		WriterStream(java.io.PrintWriter writer) {
			this.writer = writer;
		}

		@Override
		public void write(int b) {
			writer.write(b);
		}

		@Override
		public void write(byte[] b, int off, int len) {
			writer.write(new String(b, off, len, java.nio.charset.StandardCharsets.UTF_8));
		}

		@Override
		public void flush() {
			writer.flush();
		}
	}
}
