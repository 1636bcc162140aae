package org.triad.examples.hospital;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The hospital demo ({@code ./triad demo}): the delivery in the simulated hospital, with progress lines and pictures. */
class HospitalDemoTest {

	@Test
	void theDemoDeliversTheGauzePrintingProgressAndWritesPictures(@TempDir Path dir) throws Exception {
		StringWriter out = new StringWriter();
		StringWriter err = new StringWriter();
		int code = HospitalDemo.run(new String[] { "-o", dir.toString(), "--close-fire-door-at", "43" }, new PrintWriter(out, true),
				new PrintWriter(err, true));
		List<String> lines = Arrays.asList(out.toString().split("\\R"));
		assertEquals(0, code, out + err.toString());
		assertTrue(lines.contains("[   0.0 s] task CollectAndDeliver(gauze, storage, ward1) started"), out::toString);
		assertTrue(lines.contains("[  25.5 s] action Courier.move(c1, storage) succeeded; robot (4.00, 17.88) at storage, battery 89.6 %"), out::toString);
		assertTrue(lines.stream().anyMatch(l -> l.contains("robot: moveAlong[c2, c3] failed DOOR_CLOSED")), out::toString);
		assertTrue(lines.stream().anyMatch(l -> l.contains("replanning Delivered(gauze, ward1) (1 of 3)")), out::toString);
		assertTrue(lines.contains("gauze is now in ward1"), out::toString);
		// the gauze's round (round the closed fire door) leaves too little for the trip upstairs with its reserve: the plan
		// itself charges at the dock on the way, and the courier gets there with the battery the models said
		assertTrue(lines.stream().anyMatch(l -> l.contains("plan for Delivered(insulin, ward4): ") && l.contains("Courier.recharge(lobby)")),
				out::toString);
		assertTrue(lines.stream().anyMatch(l -> l.contains("action Building.ride(lift, c7, d1) succeeded")), out::toString);
		// the cabin carries the courier between floors: the battery pays for driving in and out, 5.6 m at 0.5 % a metre, as the models' ride drains
		double before = battery(lines, "Building.ride(lift, c7, d1) started");
		double after = battery(lines, "action Building.ride(lift, c7, d1) succeeded");
		assertEquals(2.8, before - after, 0.2, before + " % before the ride, " + after + " % after it");
		assertTrue(lines.stream().anyMatch(l -> l.startsWith("Completed: insulin is now in ward4")), out::toString);
		assertTrue(lines.contains("Pictures written to " + dir.toAbsolutePath().normalize() + ":"), out::toString);
		for (String picture : List.of("delivery.png", "delivery.gif", "delivery.html")) {
			assertTrue(Files.size(dir.resolve(picture)) > 1000, picture);
		}
	}

	/** The battery the first line containing {@code marker} reports ({@code ..., battery 61.8 %}). */
	private static double battery(List<String> lines, String marker) {
		String line = lines.stream().filter(l -> l.contains(marker)).findFirst().orElseThrow(() -> new AssertionError("no line " + marker));
		java.util.regex.Matcher m = java.util.regex.Pattern.compile("battery ([0-9.]+) %").matcher(line);
		assertTrue(m.find(), line);
		return Double.parseDouble(m.group(1));
	}

	@Test
	void aNegativeDoorTimeIsAUserError() {
		StringWriter out = new StringWriter();
		StringWriter err = new StringWriter();
		int code = HospitalDemo.run(new String[] { "--close-fire-door-at", "-5" }, new PrintWriter(out, true), new PrintWriter(err, true));
		assertEquals(2, code);
		assertEquals("triad demo: --close-fire-door-at takes a time in seconds >= 0, not -5.0", err.toString().strip());
	}
}
