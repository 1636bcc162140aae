package org.triad.examples.hospital;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;

import org.triad.refarc.Status;
import org.triad.runtime.app.TaskInstance;

import generated.hospital.tasks.CollectAndDeliver;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * The hospital application's demo, its own main: the delivery, end to end through RefArc, on the
 * dyn4j simulation of the hospital. {@code ./triad demo} launches it on this module's class path
 * (the command-line tool knows no example; see cli's {@code ApplicationLauncher}).
 */
@Command(name = "triad demo", mixinStandardHelpOptions = true,
		description = { "Run the hospital demo: the evaluation's delivery task (collect gauze in storage, deliver it to ward 1),",
				"planned at runtime through RefArc and executed by a simulated robot on the hospital floor (dyn4j),",
				"printing every step with the robot's position, then writing pictures of the run (PNG, GIF, HTML).",
				"Exit code: 0 when the task completed, 1 when it was aborted." })
public final class HospitalDemo implements Callable<Integer> {
	public static void main(String[] args) {
		org.triad.runtime.app.LauncherWatch.exitWithLauncher(System.err::println); // started by ./triad demo: end with it
		System.exit(run(args, new PrintWriter(System.out, true), new PrintWriter(System.err, true)));
	}

	/** Runs the demo with {@code args} and returns its exit code: 0 completed, 1 aborted, 2 bad options (one line on {@code err}). */
	public static int run(String[] args, PrintWriter out, PrintWriter err) {
		CommandLine cl = new CommandLine(new HospitalDemo());
		cl.setOut(out);
		cl.setErr(err);
		cl.setExecutionExceptionHandler((ex, commandLine, parseResult) -> {
			commandLine.getErr().println("triad demo: " + (ex.getMessage() == null ? ex.getClass().getSimpleName() : ex.getMessage()));
			return 2;
		});
		return cl.execute(args);
	}

	@Option(names = { "-o", "--out" }, paramLabel = "DIR", description = "where to write the pictures (default: ${DEFAULT-VALUE})")
	private Path out = Path.of("triad-demo");

	@Option(names = "--seed", paramLabel = "N", description = "the simulation's random seed (default: ${DEFAULT-VALUE})")
	private long seed = 42;

	@Option(names = "--close-fire-door-at", paramLabel = "SECONDS",
			description = "close the fire door between c2 and c3 at this virtual time, to watch RefArc re-plan round the ring (e.g. 40)")
	private Double closeFireDoorAt;

	@CommandLine.Spec
	private CommandLine.Model.CommandSpec spec;

	@Override
	public Integer call() {
		PrintWriter w = spec.commandLine().getOut();
		if (closeFireDoorAt != null && (!(closeFireDoorAt >= 0) || closeFireDoorAt.isInfinite())) {
			throw new IllegalArgumentException("--close-fire-door-at takes a time in seconds >= 0, not " + closeFireDoorAt);
		}
		// the pictures are written after the simulation: a folder that cannot take them is refused before it
		checkWritable(out);
		HospitalSimulation hospital = new HospitalSimulation(seed);
		if (closeFireDoorAt != null) {
			hospital.sim().at(closeFireDoorAt).closeDoor(HospitalFloor.FIRE_DOOR);
		}
		TaskInstance task = new CollectAndDeliver(hospital.objects().item("gauze"), hospital.objects().room("storage"),
				hospital.objects().room("ward1"));
		w.println("Triad demo: " + task.describe() + " in the simulated hospital (dyn4j, seed " + seed + "),");
		w.println("planned at runtime through RefArc (Morning situation: robot and Alice in the lobby, supplies in storage)"
				+ (closeFireDoorAt == null ? "" : String.format(Locale.ROOT, "; the fire door closes at %.1f s", closeFireDoorAt)));
		hospital.platformLog().observe(e -> {
			if (!e.success()) {
				w.println(line(hospital, "  robot: " + e.call() + " failed " + e.failure() + ": " + e.detail()));
			}
		});
		HospitalRun run = hospital.run(task, status -> w.println(line(hospital, describe(hospital, status))));
		// then upstairs: the pharmacy's door and the lift, world actions the building executes (both floors in the pictures)
		TaskInstance upstairs = new CollectAndDeliver(hospital.objects().item("insulin"), hospital.objects().room("pharmacy"),
				hospital.objects().room("ward4"));
		HospitalRun second = null;
		// no charge first: the plan keeps the 5 % reserve, and the models' metres are what the simulated courier drives
		// (the lift's ride included: models/hospital/README.md, "What the courier drains"), so the planner charges on
		// the way when the trip needs it
		boolean ready = run.completed();
		if (ready) {
			w.println(line(hospital, "then " + upstairs.describe() + ": from the pharmacy on floor 0 to ward 4 on floor 1, by the lift"));
			second = hospital.run(upstairs, status -> w.println(line(hospital, describe(hospital, status))));
		}
		List<Path> pictures = hospital.writePictures(out, "delivery");
		w.printf(Locale.ROOT, "%s after %.1f s of simulated time (%.1f s wall clock, %.0fx real time)%n",
				run.completed() ? "Completed" : "Aborted", run.simSeconds(), run.wallSeconds(), run.realTimeFactor());
		w.println("gauze is now in " + hospital.sim().item("gauze").room().map(r -> r.name()).orElse("no room"));
		if (second != null) {
			w.printf(Locale.ROOT, "%s: insulin is now in %s (%.1f s of simulated time, floor 1 drawn east of floor 0)%n",
					second.completed() ? "Completed" : "Aborted", hospital.sim().item("insulin").room().map(r -> r.name()).orElse("no room"),
					second.simSeconds());
		}
		w.printf(Locale.ROOT, "battery %.1f %% (%.0f J per metre driven of %.0f kJ; the Recharge task charges it at the dock in the %s)%n",
				hospital.courier().battery(), hospital.courier().robot().battery().joulesPerMetre(),
				hospital.courier().robot().battery().capacityJoules() / 1000, HospitalBuilding.DOCK);
		w.println("Pictures written to " + out.toAbsolutePath().normalize() + ":");
		w.println("  " + pictures.get(0).getFileName() + "   the trajectory with numbered action markers");
		w.println("  " + pictures.get(1).getFileName() + "   an animated replay");
		w.println("  " + pictures.get(2).getFileName() + "  a replay to open in a browser");
		return run.completed() && second != null && second.completed() ? 0 : 1;
	}

	private static String describe(HospitalSimulation hospital, Status status) {
		if (status instanceof Status.ActionStarted || status instanceof Status.ActionSucceeded || status instanceof Status.ActionFailed) {
			return status + "; robot " + hospital.robotWhereabouts();
		}
		return status.toString();
	}

	private static String line(HospitalSimulation hospital, String text) {
		return String.format(Locale.ROOT, "[%6.1f s] %s", hospital.sim().time(), text);
	}

	private static void checkWritable(Path dir) {
		if (java.nio.file.Files.exists(dir) && !java.nio.file.Files.isDirectory(dir)) {
			throw new IllegalArgumentException("-o " + dir + ": not a folder (a file of that name exists)");
		}
		try {
			java.nio.file.Files.createDirectories(dir);
			java.nio.file.Files.delete(java.nio.file.Files.createTempFile(dir, ".triad-", ".probe"));
		} catch (java.nio.file.FileSystemException e) {
			throw new IllegalArgumentException("-o " + dir + ": cannot write pictures there: "
					+ (e.getReason() != null ? e.getReason() : e.getClass().getSimpleName()) + " (" + e.getFile() + ")");
		} catch (java.io.IOException e) {
			throw new IllegalArgumentException("-o " + dir + ": cannot write pictures there: " + e);
		}
	}
}
