package org.triad.generator.arc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Automata and generic components, generated, compiled and run on the component runtime: guards
 * over port values and variables, actions that assign and send, transitions without a trigger,
 * messages no transition takes, a hand-written subclass refining a generated automaton (TOP
 * pattern), and type parameters in ports, variables and subcomponents.
 */
class AutomatonGeneratorTest {
	private static final String COUNTER = """
			package demo;
			component Counter(int limit) {
			  port in Integer tick;
			  port in String reset;
			  port out int count;
			  port out String alarm;
			  var int total = 0;
			  automaton {
			    initial state Counting;
			    state Full;
			    Counting -> Counting on tick [total + tick < limit] / { total = total + tick; count = total; };
			    Counting -> Full on tick [total + tick >= limit] / { total = limit; count = total; alarm = "full at " + total; };
			    Full -> Counting on reset [reset == "now"] / { total = 0; };
			    Full -> Full on tick / { count = total; };
			  }
			}
			""";
	private static final String DOOR = """
			package demo;
			component Door {
			  port in String command;
			  port out String log;
			  var int opened = 0;
			  automaton {
			    initial state Closed;
			    state Open;
			    state Counted;
			    Closed -> Open on command [command == "open"] / { log = "opening"; };
			    Open -> Counted / { opened = opened + 1; log = "opened " + opened + " times"; };
			    Counted -> Closed on command [command == "close"] / { log = "closed"; };
			  }
			}
			""";
	/** The hand-written refinement of Door: trims commands, and logs what no transition takes instead of failing. */
	private static final String DOOR_JAVA = """
			package demo;
			public class Door extends DoorTOP {
			    @Override protected void onCommand(String command) throws Exception { super.onCommand(command.trim()); }
			    @Override protected void unhandled(String port, Object message) { log.send("ignored " + message + " in " + currentState()); }
			}
			""";
	private static final String LATCH = """
			package demo;
			component Latch<T> {
			  port in T value;
			  port in Boolean release;
			  port out T out;
			  var T held = null;
			  var java.util.List<T> seen = new java.util.ArrayList<>();
			  automaton {
			    initial state Empty;
			    state Holding;
			    Empty -> Holding on value / { held = value; seen.add(value); };
			    Holding -> Holding on value / { held = value; seen.add(value); };
			    Holding -> Empty on release [release] / { out = held; held = null; };
			    Holding -> Holding on release [!release] / { };
			  }
			}
			""";
	private static final String RELAY = """
			package app;
			import demo.*;
			component Relay<T> {
			  port in T in;
			  port in Boolean go;
			  port out T out;
			  Latch<T> latch;
			  in -> latch.value;
			  go -> latch.release;
			  latch.out -> out;
			}
			""";
	private static final String HARNESS = """
			package app;
			import java.util.ArrayList;
			import java.util.List;
			import org.triad.runtime.component.DeterministicScheduler;
			import org.triad.runtime.component.Scheduler;
			public class Harness {
			    public static List<Object> counter() {
			        demo.Counter c = new demo.Counter(6);
			        List<Object> seen = new ArrayList<>();
			        c.count.observe(seen::add);
			        c.alarm.observe(seen::add);
			        DeterministicScheduler s = Scheduler.deterministic();
			        s.deploy(c);
			        for (Object m : List.of(2, 3, 4, 1, "later", "now", 1)) {
			            if (m instanceof Integer i) { s.send(c.tick, i); } else { s.send(c.reset, (String) m); }
			            s.runUntilIdle();
			        }
			        seen.add(c.currentState().name());
			        s.unhandledFaults().forEach(f -> seen.add(f.causeDescription()));
			        return seen;
			    }
			    public static List<Object> door() {
			        demo.Door d = new demo.Door();
			        List<Object> seen = new ArrayList<>();
			        d.log.observe(seen::add);
			        DeterministicScheduler s = Scheduler.deterministic();
			        s.deploy(d);
			        for (String m : List.of(" open ", "open", "close", "open")) {
			            s.send(d.command, m);
			            s.runUntilIdle();
			        }
			        seen.add(d.currentState().name());
			        seen.addAll(s.unhandledFaults());
			        return seen;
			    }
			    public static List<Object> relay() {
			        Relay<String> r = new Relay<>();
			        List<Object> seen = new ArrayList<>();
			        r.out.observe(seen::add);
			        DeterministicScheduler s = Scheduler.deterministic();
			        s.deploy(r);
			        s.send(r.in, "a");
			        s.send(r.in, "b");
			        s.send(r.go, false);
			        s.send(r.go, true);
			        s.send(r.in, "c");
			        s.send(r.go, true);
			        s.runUntilIdle();
			        seen.addAll(s.unhandledFaults());
			        return seen;
			    }
			}
			""";

	@TempDir
	Path work;

	@Test
	void automataAndGenericComponentsCompileAndRun() throws Exception {
		Path models = work.resolve("models");
		ArcGeneratorTest.write(models, Map.of("demo/Counter.arc", COUNTER, "demo/Door.arc", DOOR, "demo/Latch.arc", LATCH, "app/Relay.arc", RELAY));
		Path hand = work.resolve("hand");
		ArcGeneratorTest.write(hand, Map.of("demo/Door.java", DOOR_JAVA, "app/Harness.java", HARNESS));
		Path src = work.resolve("src");
		List<Path> generated = ArcJavaGenerator.generate(models, src, HandwrittenCode.in(hand), List.of());
		// a TOP class only where hand-written code exists
		assertEquals(List.of("app/Relay.java", "demo/Counter.java", "demo/DoorTOP.java", "demo/Latch.java"),
				generated.stream().map(p -> src.relativize(p).toString().replace('\\', '/')).sorted().toList());
		assertFalse(Files.readString(src.resolve("demo/Counter.java")).contains("abstract"), "an automaton without hand-written code is complete");
		ArcGeneratorTest.write(src, Map.of("demo/Door.java", DOOR_JAVA, "app/Harness.java", HARNESS));
		Path classes = Files.createDirectories(work.resolve("classes"));
		ArcGeneratorTest.compile(src, classes);
		try (URLClassLoader loader = new URLClassLoader(new URL[] { classes.toUri().toURL() }, getClass().getClassLoader())) {
			Class<?> harness = loader.loadClass("app.Harness");
			List<?> counter = (List<?>) harness.getMethod("counter").invoke(null);
			assertEquals(List.of(2, 5, 6, "full at 6", 6, 1, "Counting",
					"IllegalStateException: no transition of state Full of Counter takes later on port reset"), counter);
			// the completion transition Open -> Counted runs right after Closed -> Open; the subclass trims and logs the unhandled
			assertEquals(List.of("opening", "opened 1 times", "ignored open in Counted", "closed", "opening", "opened 2 times", "Counted"),
					harness.getMethod("door").invoke(null));
			assertEquals(List.of("b", "c"), harness.getMethod("relay").invoke(null));
		}
	}

	@Test
	void anAutomatonThatLoopsWithoutInputIsAFault() throws Exception {
		Path models = work.resolve("models");
		ArcGeneratorTest.write(models, Map.of("demo/Spin.arc", """
				package demo;
				component Spin {
				  port in int go;
				  var int turns = 0;
				  automaton {
				    initial state A;
				    state B;
				    A -> B / { turns = turns + 1; };
				    B -> A;
				  }
				}
				"""));
		Path src = work.resolve("src");
		ArcJavaGenerator.generate(models, src, HandwrittenCode.NONE, List.of());
		ArcGeneratorTest.write(src, Map.of("demo/Run.java", """
				package demo;
				import org.triad.runtime.component.DeterministicScheduler;
				import org.triad.runtime.component.Scheduler;
				public class Run {
				    public static String run() {
				        Spin spin = new Spin();
				        DeterministicScheduler s = Scheduler.deterministic();
				        s.deploy(spin);
				        s.send(spin.go, 1);
				        s.runUntilIdle();
				        return s.unhandledFaults().get(0).causeDescription() + " after " + spin.turns;
				    }
				}
				"""));
		Path classes = Files.createDirectories(work.resolve("classes"));
		ArcGeneratorTest.compile(src, classes);
		try (URLClassLoader loader = new URLClassLoader(new URL[] { classes.toUri().toURL() }, getClass().getClassLoader())) {
			String fault = (String) loader.loadClass("demo.Run").getMethod("run").invoke(null);
			assertTrue(fault.startsWith("IllegalStateException: Spin took 1000 transitions without a trigger in a row"), fault);
		}
	}
}
