package org.triad.generator.arc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Architectures written with MontiArc 7's constructs (our own models, after MontiArc's bumperbot,
 * elevator and montiarc-base library), generated, compiled and run in time slices on the component
 * runtime ({@code TimeSlices}), fed on their input ports: synchronous automata with initial actions,
 * hierarchical states with entry and exit actions, compute and init blocks, delayed ports breaking
 * feedback loops, multi-instance and generic subcomponents, inheritance with arguments, and data
 * types from a class diagram.
 */
class MontiArcApplicationsTest {
	/** Drives the rover: far, far, near, then far; one line per slice. */
	private static final String ROVER_HARNESS = """
			package harness;
			import java.util.*;
			import org.triad.runtime.component.TimeSlices;
			import rover.*;
			public final class RoverRun {
			    public static List<String> run() {
			        Rover rover = new Rover();
			        List<String> slice = new ArrayList<>();
			        rover.left.observe(m -> slice.add("left=" + m));
			        rover.right.observe(m -> slice.add("right=" + m));
			        rover.status.observe(m -> slice.add("status=" + m));
			        TimeSlices clock = TimeSlices.deploy(rover);
			        int[] ranges = { 80, 60, 40, 5, 5, 5, 5, 5, 5, 50, 50 };
			        List<String> lines = new ArrayList<>();
			        for (int range : ranges) {
			            clock.send(rover.range, range);
			            clock.tick();
			            lines.add(String.join(" ", slice));
			            slice.clear();
			        }
			        lines.add("faults=" + clock.scheduler().unhandledFaults());
			        return lines;
			    }
			}
			""";
	/** Simulates the shaft: the cabin moves a floor per slice while the last command was UP or DOWN. */
	private static final String LIFT_HARNESS = """
			package harness;
			import java.util.*;
			import org.triad.runtime.component.TimeSlices;
			import lift.*;
			public final class LiftRun {
			    public static List<String> run(int start, Map<Integer, Integer> presses, int slices) {
			        Lift lift = new Lift();
			        Motion[] motion = { Motion.STOP };
			        List<String> slice = new ArrayList<>();
			        lift.motion.observe(m -> { motion[0] = m; slice.add("motion=" + m); });
			        lift.door.observe(m -> slice.add("door=" + m));
			        lift.light1.observe(m -> { if (m) slice.add("light1"); });
			        lift.light2.observe(m -> { if (m) slice.add("light2"); });
			        lift.light3.observe(m -> { if (m) slice.add("light3"); });
			        TimeSlices clock = TimeSlices.deploy(lift);
			        int floor = start;
			        List<String> lines = new ArrayList<>();
			        for (int t = 0; t < slices; t++) {
			            Integer pressed = presses.get(t);
			            clock.send(lift.btn1, pressed != null && pressed == 1);
			            clock.send(lift.btn2, pressed != null && pressed == 2);
			            clock.send(lift.btn3, pressed != null && pressed == 3);
			            clock.send(lift.at1, floor == 1);
			            clock.send(lift.at2, floor == 2);
			            clock.send(lift.at3, floor == 3);
			            clock.tick();
			            lines.add(t + " floor=" + floor + " " + String.join(" ", slice));
			            slice.clear();
			            if (motion[0] == Motion.UP) floor = Math.min(3, floor + 1);
			            if (motion[0] == Motion.DOWN) floor = Math.max(1, floor - 1);
			        }
			        lines.add("faults=" + clock.scheduler().unhandledFaults());
			        return lines;
			    }
			}
			""";
	/** Drives the latch and the other library equivalents; one line per slice. */
	private static final String LOGIC_HARNESS = """
			package harness;
			import java.util.*;
			import org.triad.runtime.component.*;
			import logic.*;
			public final class LogicRun {
			    public static List<String> latch(boolean[][] sr) {
			        Latch latch = new Latch();
			        List<String> slice = new ArrayList<>();
			        latch.q0.observe(m -> slice.add("q0=" + m));
			        latch.q1.observe(m -> slice.add("q1=" + m));
			        TimeSlices clock = TimeSlices.deploy(latch);
			        List<String> lines = new ArrayList<>();
			        for (boolean[] in : sr) {
			            clock.send(latch.s, in[0]);
			            clock.send(latch.r, in[1]);
			            clock.tick();
			            lines.add(String.join(" ", slice));
			            slice.clear();
			        }
			        lines.add("order=" + clock.order());
			        return lines;
			    }
			    /** A root of one atomic component: its in ports are fed by a composed wrapper made here by hand. */
			    public static List<String> relayAndLimiter() {
			        Relay<String> relay = new Relay<>();
			        Limiter limiter = new Limiter(10);
			        List<String> lines = new ArrayList<>();
			        class Box extends ComposedComponent {
			            final InPort<String> in = inPort("in", String.class);
			            final OutPort<Object> out = outPort("out", Object.class);
			            final InPort<Integer> x = inPort("x", Integer.class);
			            final OutPort<Integer> y = outPort("y", Integer.class);
			            Box() {
			                subcomponent("relay", relay);
			                subcomponent("limiter", limiter);
			                connect(in, relay.i);
			                connect(relay.o, out);
			                connect(x, limiter.x);
			                connect(limiter.y, y);
			            }
			        }
			        Box box = new Box();
			        List<String> slice = new ArrayList<>();
			        box.out.observe(m -> slice.add("out=" + m));
			        box.y.observe(m -> slice.add("y=" + m));
			        TimeSlices clock = TimeSlices.deploy(box);
			        String[] words = { "a", "b", null };
			        int[] xs = { 3, 12, 7 };
			        for (int t = 0; t < words.length; t++) {
			            if (words[t] != null) clock.send(box.in, words[t]);
			            clock.send(box.x, xs[t]);
			            clock.tick();
			            lines.add(String.join(" ", slice));
			            slice.clear();
			        }
			        return lines;
			    }
			}
			""";

	@TempDir
	Path tmp;

	@Test
	void roverReversesAndTurnsAtANearObstacle() throws Exception {
		List<String> lines = run("rover", ROVER_HARNESS, "harness.RoverRun", "run");
		// slice 0: the initial actions (halt), then Idle -> Cruising; every receiver of a sync port takes one message a slice
		assertEquals("left=HALT right=HALT status=idle left=AHEAD right=AHEAD status=cruising", lines.get(0));
		assertEquals("", lines.get(1));
		assertEquals("", lines.get(2));
		// slice 3: range 5 < 10: reverse and start the short alarm (2 slices; its delayed ring arrives a slice later)
		assertEquals("left=REVERSE right=REVERSE status=reversing", lines.get(3));
		assertEquals("", lines.get(4));
		assertEquals("", lines.get(5));
		assertEquals("left=AHEAD right=REVERSE status=rotating", lines.get(6));
		assertEquals("", lines.get(7));
		assertEquals("", lines.get(8));
		assertEquals("", lines.get(9));
		assertEquals("left=AHEAD right=AHEAD status=cruising", lines.get(10));
		assertEquals("faults=[]", lines.get(11));
	}

	@Test
	void liftHomesThenReachesTheRequestedFloors() throws Exception {
		List<String> lines = run("lift", LIFT_HARNESS, "harness.LiftRun", "run", 2, java.util.Map.of(6, 3, 12, 2), 20);
		String all = String.join("\n", lines);
		// homing: down from floor 2 to 1, stop
		assertEquals("0 floor=2 motion=DOWN", lines.get(0));
		assertEquals("1 floor=1 motion=STOP", lines.get(1));
		// Home -> Idle enters Idle: its entry action closes the door
		assertEquals("2 floor=1 door=CLOSE", lines.get(2));
		// floor 3 requested at slice 6: its light goes on, the lift goes up, stops at 3, opens and clears the light
		assertTrue(lines.get(6).contains("light3"), all);
		assertTrue(all.contains("floor=1 light3 motion=UP"), all);
		assertTrue(all.contains("floor=3 light3 motion=STOP door=OPEN"), all);
		int open3 = indexOf(lines, "floor=3 light3 motion=STOP door=OPEN");
		assertTrue(!lines.get(open3 + 2).contains("light3"), all);
		// then floor 2, downwards
		assertTrue(all.contains("light2 motion=DOWN"), all);
		assertTrue(all.contains("floor=2 light2 motion=STOP door=OPEN"), all);
		assertEquals("faults=[]", lines.get(lines.size() - 1));
	}

	@Test
	void srLatchWithFeedbackThroughDelaysSetsAndResets() throws Exception {
		boolean[][] sr = { { true, false }, { false, false }, { false, true }, { false, true }, { false, false } };
		List<String> lines = run("logic", LOGIC_HARNESS, "harness.LogicRun", "latch", (Object) sr);
		// set: q1 on and held through the delayed feedback; reset (held two slices): q0 on once the feedback arrives, and held
		assertEquals("q0=false q1=true", lines.get(0));
		assertEquals("q0=false q1=true", lines.get(1));
		assertEquals("q0=false q1=false", lines.get(2));
		assertEquals("q0=true q1=false", lines.get(3));
		assertEquals("q0=true q1=false", lines.get(4));
	}

	@Test
	void eventAutomatonWithDelayedPortAndInheritedGenericCompute() throws Exception {
		List<String> lines = run("logic", LOGIC_HARNESS, "harness.LogicRun", "relayAndLimiter");
		assertEquals(List.of("y=3", "out=a y=10", "out=b y=7"), lines);
	}

	private static int indexOf(List<String> lines, String part) {
		for (int i = 0; i < lines.size(); i++) {
			if (lines.get(i).contains(part)) {
				return i;
			}
		}
		return -1;
	}

	@SuppressWarnings("unchecked")
	private List<String> run(String models, String harness, String harnessClass, String method, Object... args) throws Exception {
		Path src = tmp.resolve("src");
		Path classes = tmp.resolve("classes");
		Files.createDirectories(classes);
		Path folder = Path.of(getClass().getResource("/montiarc/" + models).toURI());
		ArcJavaGenerator.generate(folder, src, HandwrittenCode.NONE, List.of());
		Path h = src.resolve(harnessClass.replace('.', '/') + ".java");
		Files.createDirectories(h.getParent());
		Files.writeString(h, harness);
		ArcGeneratorTest.compile(src, classes);
		try (URLClassLoader loader = new URLClassLoader(new URL[] { classes.toUri().toURL() }, getClass().getClassLoader())) {
			for (var m : loader.loadClass(harnessClass).getMethods()) {
				if (m.getName().equals(method)) {
					return (List<String>) m.invoke(null, args);
				}
			}
		}
		throw new AssertionError("no method " + method);
	}
}
