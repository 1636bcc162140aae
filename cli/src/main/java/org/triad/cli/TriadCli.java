package org.triad.cli;

import java.io.PrintWriter;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/** The {@code triad} command: the entry point of the toolchain for every role. */
@Command(name = "triad", mixinStandardHelpOptions = true, version = "Triad 0.1.0",
		description = "Model-driven service robotics: check, generate and run applications modeled by domain, robotics and integration experts.",
		subcommands = { DemoCommand.class, CheckCommand.class, GenerateCommand.class, RunCommand.class, ServeCommand.class, PddlCommand.class, SolveCommand.class, ArcCommand.class, LspCommand.class,
				RobotCommand.class, BrokerCommand.class, UsersCommand.class, NewCommand.class,
				CommandLine.HelpCommand.class })
public final class TriadCli implements Runnable {
	@CommandLine.Spec
	private CommandLine.Model.CommandSpec spec;

	@Override
	public void run() {
		spec.commandLine().usage(spec.commandLine().getOut());
	}

	public static void main(String[] args) {
		System.exit(execute(args, new PrintWriter(System.out, true), new PrintWriter(System.err, true)));
	}

	/** Runs the command line and returns its exit code; unexpected failures are printed as one line, never a stack trace. */
	public static int execute(String[] args, PrintWriter out, PrintWriter err) {
		CommandLine cl = new CommandLine(new TriadCli());
		cl.setOut(out);
		cl.setErr(err);
		// the demo's options belong to the application's demo, which parses them
		cl.getSubcommands().get("demo").setUnmatchedOptionsArePositionalParams(true);
		cl.setExecutionExceptionHandler((ex, commandLine, parseResult) -> {
			commandLine.getErr().println("triad " + commandLine.getCommandName() + ": " + FailureMessage.of(ex));
			return 2;
		});
		return cl.execute(args);
	}
}
