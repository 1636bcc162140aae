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

	@Option(names = "--speed", paramLabel = "FACTOR", description = "virtual seconds per wall-clock second (default: ${DEFAULT-VALUE})")
	private double speed = 10;

	@Option(names = "--seed", paramLabel = "N", description = "the simulation's random seed (default: ${DEFAULT-VALUE})")
	private long seed = 42;

	@Option(names = { "-o", "--out" }, paramLabel = "DIR", description = "draw each robot's trajectory into DIR/SERIAL.png after every order")
	private Path out;

	@Option(names = "--close-fire-door-at", paramLabel = "SECONDS", description = "close the fire door between c2 and c3 at this virtual time")
	private Double closeFireDoorAt;

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
		credentials.apply();
		MqttCredentialsOption.warnIfPlain("robot", broker, spec.commandLine().getErr());
		List<String> args = new ArrayList<>(List.of("--broker", broker, "--seed", Long.toString(seed), "--speed", Double.toString(speed)));
		if (serial != null) {
			args.addAll(List.of("--serial", serial));
		}
		if (count != null) {
			args.addAll(List.of("--count", Integer.toString(count)));
		}
		if (out != null) {
			args.addAll(List.of("--out", out.toString()));
		}
		if (closeFireDoorAt != null) {
			args.addAll(List.of("--close-fire-door-at", Double.toString(closeFireDoorAt)));
		}
		// the couriers are the hospital application's code, run on its class path (the CLI knows no example)
		return ApplicationLauncher.bundled(DemoCommand.APPLICATION).run("robot", args, spec.commandLine().getOut(), spec.commandLine().getErr());
	}
}
