package org.triad.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;

import org.triad.examples.hospital.HospitalFloor;
import org.triad.examples.hospital.HospitalRun;
import org.triad.examples.hospital.HospitalSimulation;
import org.triad.refarc.Status;
import org.triad.runtime.app.TaskInstance;

import generated.hospital.tasks.CollectAndDeliver;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code triad demo}: the hospital delivery, end to end through RefArc, on the dyn4j simulation of the hospital. */
@Command(name = "demo", mixinStandardHelpOptions = true,
		description = { "Run the hospital demo: the evaluation's delivery task (collect gauze in storage, deliver it to ward 1),",
				"planned at runtime through RefArc and executed by a simulated robot on the hospital floor (dyn4j),",
				"printing every step with the robot's position, then writing pictures of the run (PNG, GIF, HTML).",
				"Exit code: 0 when the task completed, 1 when it was aborted." })
public final class DemoCommand implements Callable<Integer> {
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
			throw new ModelSession.UserError("--close-fire-door-at takes a time in seconds >= 0, not " + closeFireDoorAt);
		}
		// the pictures are written after the simulation: a folder that cannot take them is refused before it
		OutputFolder.check(out, "-o");
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
		List<Path> pictures = hospital.writePictures(out, "delivery");
		w.printf(Locale.ROOT, "%s after %.1f s of simulated time (%.1f s wall clock, %.0fx real time)%n",
				run.completed() ? "Completed" : "Aborted", run.simSeconds(), run.wallSeconds(), run.realTimeFactor());
		w.println("gauze is now in " + hospital.sim().item("gauze").room().map(r -> r.name()).orElse("no room"));
		w.println("Pictures written to " + out.toAbsolutePath().normalize() + ":");
		w.println("  " + pictures.get(0).getFileName() + "   the trajectory with numbered action markers");
		w.println("  " + pictures.get(1).getFileName() + "   an animated replay");
		w.println("  " + pictures.get(2).getFileName() + "  a replay to open in a browser");
		return run.completed() ? 0 : 1;
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
}
