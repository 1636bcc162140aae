package org.triad.tests.vda5050;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.triad.cli.TriadCli;
import org.triad.examples.hospital.vda5050.SimulatedAgv;
import org.triad.vda5050.broker.MosquittoBroker;

/** {@code triad run --robots vda5050:...} and {@code triad robot} as a user runs them, on a real Mosquitto. */
class VdaCommandsTest {
	private static final String HOSPITAL = "../models/hospital/src/main/models";

	private record Result(int code, List<String> lines, String err) {
	}

	private static Result triad(String... args) {
		StringWriter out = new StringWriter();
		StringWriter err = new StringWriter();
		int code = TriadCli.execute(args, new PrintWriter(out, true), new PrintWriter(err, true));
		return new Result(code, Arrays.asList(out.toString().split("\\R")), err.toString());
	}

	@Test
	void aTaskRunsOnASimulatedRobotThroughTheBroker() {
		try (MosquittoBroker broker = MosquittoBroker.start(Path.of("target", "mosquitto", "VdaCommandsTest"));
				SimulatedAgv robot = new SimulatedAgv(broker.url(), "courier-7", 42, 50, null, line -> { }).start()) {
			Result r = triad("run", HOSPITAL, "--state", "Morning.state", "--task", "Fetch(syringe, storage, xray)", "--robots",
					"vda5050:" + broker.url(), "--serial", "courier-7");
			assertEquals(0, r.code(), String.join("\n", r.lines()) + r.err());
			assertEquals("task Fetch(syringe, storage, xray) completed", r.lines().get(r.lines().size() - 1));
			assertTrue(robot.statesSent() > 0);
		}
	}

	@Test
	void noBrokerIsOneLineNamingHostAndPortAndExitCode2() {
		int port = MosquittoBroker.freePort();
		Result r = triad("run", HOSPITAL, "--state", "Morning.state", "--task", "GoTo(ward3)", "--robots", "vda5050:tcp://127.0.0.1:" + port);
		assertEquals(2, r.code());
		// plain TCP is named as such first (./triad broker's default is ssl://), then the one line of the error
		List<String> lines = r.err().lines().toList();
		assertEquals(2, lines.size(), r.err());
		assertTrue(lines.get(0).startsWith("triad run: warning: tcp://127.0.0.1:" + port + " is plain TCP"), r.err());
		assertTrue(lines.get(1).startsWith("triad run: no MQTT broker at 127.0.0.1:" + port + " "), r.err());
	}

	@Test
	void badRobotsOptionIsOneLineAndExitCode2() {
		Result r = triad("run", HOSPITAL, "--state", "Morning.state", "--task", "GoTo(ward3)", "--robots", "ros2:localhost");
		assertEquals(2, r.code());
		assertEquals("triad run: --robots takes vda5050:ssl://HOST:PORT (or vda5050:tcp://HOST:PORT), not 'ros2:localhost'", r.err().strip());
		Result robot = triad("robot", "--broker", "tcp://127.0.0.1:" + MosquittoBroker.freePort(), "--serial", "a", "--count", "2");
		assertEquals(2, robot.code());
		assertTrue(robot.err().strip().endsWith("triad robot: give --serial S or --count N, not both"), robot.err());
	}
}
