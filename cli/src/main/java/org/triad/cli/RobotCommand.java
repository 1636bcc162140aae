package org.triad.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;


import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code triad robot --broker tcp://HOST:PORT}: simulated hospital couriers as VDA 5050 robots on a broker. */
@Command(name = "robot", mixinStandardHelpOptions = true,
		description = { "Run simulated couriers of the dyn4j hospital as VDA 5050 2.1 robots (AGVs) on an MQTT broker, until stopped (Ctrl-C).",
				"All share ONE building (one simulation, one clock): they meet in its corridors, and each contact between two robots is printed as a line 'contact A B at (x, y) t=T s'.",
				"Each publishes connection (last will CONNECTIONBROKEN), state, visualization and factsheet on uagv/v2/triad/SERIAL/...",
				"and executes orders and instant actions from master control (./triad run ... --robots vda5050:ssl://HOST:PORT).",
				"Exit code 2 for bad options or a broker that does not answer." })
public final class RobotCommand implements Callable<Integer> {
	@Option(names = "--broker", required = true, paramLabel = "ssl://HOST:PORT", description = "the MQTT broker (e.g. from ./triad broker)")
	private String broker;

	@CommandLine.Mixin
	private MqttCredentialsOption credentials = new MqttCredentialsOption();

	@Option(names = "--serial", paramLabel = "SERIAL", description = "the robot's serial number (default: courier-1)")
	private String serial;

	@Option(names = "--count", paramLabel = "N", description = "run N robots in this process: serial numbers courier-1 .. courier-N")
	private Integer count;

	@Option(names = "--speed", paramLabel = "FACTOR", description = "virtual seconds per wall-clock second, or 'max' for as fast as the machine allows (default: ${DEFAULT-VALUE})")
	private String speed = "10";

	@Option(names = "--seed", paramLabel = "N", description = "the simulation's random seed (default: ${DEFAULT-VALUE})")
	private long seed = 42;

	@Option(names = { "-o", "--out" }, paramLabel = "DIR", description = "draw each robot's trajectory into DIR/SERIAL.png after every order")
	private Path out;

	@Option(names = "--close-fire-door-at", paramLabel = "SECONDS", description = "close the fire door between c2 and c3 at this virtual time")
	private Double closeFireDoorAt;

	@Option(names = "--battery", paramLabel = "PERCENT", description = "every robot's initial battery charge, 0..100 (default: full); it drains 50 J per metre driven and charges at the lobby's dock")
	private Double battery;

	@CommandLine.Spec
	private CommandLine.Model.CommandSpec spec;

	@Override
	public Integer call() {
		if (serial != null && count != null) {
			throw new ModelSession.UserError("give --serial S or --count N, not both");
		}
		if (count != null && count < 1) {
			throw new ModelSession.UserError("--count takes a number of robots >= 1, not " + count);
		}
		if (!speed.equals("max")) {
			double factor;
			try {
				factor = Double.parseDouble(speed);
			} catch (NumberFormatException e) {
				factor = Double.NaN;
			}
			if (!(factor > 0) || Double.isInfinite(factor)) {
				throw new ModelSession.UserError("--speed takes a positive factor or 'max', not '" + speed + "'");
			}
		}
		credentials.apply();
		MqttCredentialsOption.warnIfPlain("robot", broker, spec.commandLine().getErr());
		List<String> args = new ArrayList<>(List.of("--broker", broker, "--seed", Long.toString(seed), "--speed", speed));
		if (serial != null) {
			args.addAll(List.of("--serial", serial));
		}
		if (count != null) {
			args.addAll(List.of("--count", Integer.toString(count)));
		}
		if (out != null) {
			args.addAll(List.of("--out", out.toString()));
		}
		if (battery != null) {
			args.addAll(List.of("--battery", Double.toString(battery)));
		}
		if (closeFireDoorAt != null) {
			args.addAll(List.of("--close-fire-door-at", Double.toString(closeFireDoorAt)));
		}
		// the couriers are the hospital application's code, run on its class path (the CLI knows no example)
		return ApplicationLauncher.bundled(DemoCommand.APPLICATION).run("robot", args, spec.commandLine().getOut(), spec.commandLine().getErr());
	}
}
