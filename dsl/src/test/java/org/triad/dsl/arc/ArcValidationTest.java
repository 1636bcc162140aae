package org.triad.dsl.arc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.triad.dsl.arc.ArcModel;
import org.triad.dsl.arc.ArcPort;
import org.triad.dsl.arc.Assignment;
import org.triad.dsl.arc.BinaryExpression;
import org.triad.dsl.arc.Transition;
import org.triad.dsl.semantics.ArcModels;
import org.triad.dsl.validation.ArcIssueCodes;
import org.triad.dsl.validation.CommonIssueCodes;

/** One bad model per diagnostic code of .arc (exact code and line), and valid models that pass every rule. */
class ArcValidationTest {
	private static final String SENSOR = """
			package demo;
			component Sensor {
			  port in int tick;
			  port out Double value;
			}
			""";
	private static final String FILTER = """
			package demo;
			component Filter(double gain) {
			  port in double raw;
			  port out double smooth;
			  automaton {
			    initial state Idle;
			    state Busy;
			    Idle -> Busy on raw [raw > 0.5 && gain != 0] / { smooth = raw * gain; };
			    Busy -> Idle;
			  }
			}
			""";
	private static final String SINK = """
			package other;
			import org.triad.runtime.component.ComponentFault;
			component Sink {
			  port in Double in;
			  port in ComponentFault fault;
			}
			""";
	/** Line 10 is the connector the bad variants replace. */
	private static final String SYSTEM = """
			package demo;
			import other.Sink;
			component System {
			  port in int tick;
			  port out double out;
			  Sensor sensor;
			  Filter filter(2.0);
			  Sink sink;
			  sensor.value -> filter.raw;
			  tick -> sensor.tick;
			  filter.smooth -> out, sink.in;
			  faults -> sink.fault;
			}
			""";

	private static List<String> found(String systemText) {
		return found(Map.of("System.arc", systemText));
	}

	private static List<String> found(Map<String, String> replaced) {
		Map<String, String> files = new LinkedHashMap<>();
		files.put("Sensor.arc", SENSOR);
		files.put("Filter.arc", FILTER);
		files.put("Sink.arc", SINK);
		files.put("System.arc", SYSTEM);
		files.putAll(replaced);
		return ArcModelSet.of(files).issues().stream().filter(ArcModelSet.Found::error).map(f -> f.file() + ":" + f.line() + " " + f.code()).toList();
	}

	private static List<String> warnings(String systemText) {
		Map<String, String> files = new LinkedHashMap<>(Map.of("Sensor.arc", SENSOR, "Filter.arc", FILTER, "Sink.arc", SINK));
		files.put("System.arc", systemText);
		return ArcModelSet.of(files).issues().stream().filter(f -> !f.error()).map(f -> f.file() + ":" + f.line() + " " + f.code()).toList();
	}

	private static String system(String line10) {
		return SYSTEM.replace("  tick -> sensor.tick;\n", line10.isEmpty() ? "\n" : "  " + line10 + "\n");
	}

	@Test
	void validModelsHaveNoDiagnostics() {
		ArcModelSet set = ArcModelSet.of(Map.of("Sensor.arc", SENSOR, "Filter.arc", FILTER, "Sink.arc", SINK, "System.arc", SYSTEM));
		assertEquals(List.of(), set.issues());
	}

	@Test
	void guardsAndActionsAreParsedExpressions() {
		ArcModel filter = ArcModelSet.of("Filter.arc", FILTER).model("Filter.arc");
		Transition t = filter.getComponent().getAutomata().get(0).getTransitions().get(0);
		assertEquals("raw", t.getTrigger().getName());
		BinaryExpression guard = (BinaryExpression) t.getGuard();
		assertEquals("&&", guard.getOp());
		assertEquals(">", ((BinaryExpression) guard.getLeft()).getOp());
		Assignment send = (Assignment) t.getActions().get(0);
		assertEquals("smooth", send.getTarget().getName());
		assertEquals("*", ((BinaryExpression) send.getValue()).getOp());
		assertEquals(List.of("raw", "smooth"), ArcModels.ports(filter.getComponent()).stream().map(ArcPort::getName).toList());
	}

	/** Line 11 onwards are the transitions the bad variants change. */
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
			    Full -> Counting on reset [reset.equals("now")] / { total = 0; };
			    Full -> Full on tick / { count = total; };
			  }
			}
			""";

	private static List<String> counter(String from, String to) {
		assertTrue(COUNTER.contains(from), from);
		return ArcModelSet.of("Counter.arc", COUNTER.replace(from, to)).issues().stream()
				.map(f -> f.file() + ":" + f.line() + " " + (f.error() ? "" : "warning ") + f.code()).toList();
	}

	@Test
	void aValidAutomatonHasNoDiagnostics() {
		assertEquals(List.of(), ArcModelSet.of("Counter.arc", COUNTER).issues());
	}

	@Test
	void unreachableStatesAreWarned() {
		assertEquals(List.of("Counter.arc:11 warning " + ArcIssueCodes.UNREACHABLE_STATE), counter("    state Full;\n", "    state Full;\n    state Lost;\n"));
		assertEquals(List.of("Counter.arc:10 warning " + ArcIssueCodes.UNREACHABLE_STATE),
				counter("    Counting -> Full on tick [total + tick >= limit]", "    Counting -> Counting on tick [total + tick >= limit]"));
	}

	@Test
	void transitionsThatCanFireTogetherAreNondeterministic() {
		assertEquals(List.of("Counter.arc:15 " + ArcIssueCodes.NONDETERMINISTIC_TRANSITIONS),
				counter("    Full -> Full on tick / { count = total; };\n", "    Full -> Full on tick / { count = total; };\n    Full -> Counting on tick [total > 0] / { total = 0; };\n"));
		assertEquals(List.of("Counter.arc:12 " + ArcIssueCodes.NONDETERMINISTIC_TRANSITIONS),
				counter("[total + tick >= limit]", "[total + tick < limit]"));
		// different triggers, or guards that differ, are not flagged
		assertEquals(List.of(), counter("    Full -> Counting on reset [reset.equals(\"now\")]", "    Full -> Counting on reset"));
	}

	@Test
	void guardsMustBeBoolean() {
		assertEquals(List.of("Counter.arc:11 " + ArcIssueCodes.EXPRESSION_TYPE), counter("[total + tick < limit]", "[total + tick]"));
		assertEquals(List.of("Counter.arc:11 " + ArcIssueCodes.EXPRESSION_TYPE), counter("[total + tick < limit]", "[total < limit && tick]"));
	}

	@Test
	void actionsMustTypeCheck() {
		assertEquals(List.of("Counter.arc:14 " + ArcIssueCodes.EXPRESSION_TYPE), counter("/ { count = total; }", "/ { total = \"many\"; }"));
		assertEquals(List.of("Counter.arc:14 " + ArcIssueCodes.EXPRESSION_TYPE), counter("/ { count = total; }", "/ { alarm = total; }"));
		assertEquals(List.of("Counter.arc:14 " + ArcIssueCodes.EXPRESSION_TYPE), counter("/ { count = total; }", "/ { count = total - \"one\"; }"));
		assertEquals(List.of("Counter.arc:14 " + ArcIssueCodes.EXPRESSION_TYPE), counter("/ { count = total; }", "/ { total; }"));
		assertEquals(List.of("Counter.arc:7 " + ArcIssueCodes.EXPRESSION_TYPE), counter("var int total = 0;", "var int total = true;"));
		// members of Java types are left to the Java compiler
		assertEquals(List.of(), counter("/ { total = 0; }", "/ { total = reset.trim().length(); }"));
		// numbers widen as in Java, and do not narrow
		assertEquals(List.of("Counter.arc:11 " + ArcIssueCodes.EXPRESSION_TYPE, "Counter.arc:12 " + ArcIssueCodes.EXPRESSION_TYPE,
				"Counter.arc:14 " + ArcIssueCodes.EXPRESSION_TYPE), counter("var int total = 0;", "var long total = 0;"));
	}

	@Test
	void anActionSendsOnOutgoingPortsOnly() {
		assertEquals(List.of("Counter.arc:14 " + ArcIssueCodes.SEND_ON_INPUT), counter("/ { count = total; }", "/ { tick = total; }"));
	}

	@Test
	void configurationParametersAreNotAssignable() {
		assertEquals(List.of("Counter.arc:14 " + ArcIssueCodes.NOT_ASSIGNABLE), counter("/ { count = total; }", "/ { limit = total; }"));
	}

	@Test
	void onlyTheTriggerPortCarriesAMessage() {
		assertEquals(List.of("Counter.arc:14 " + ArcIssueCodes.PORT_NOT_READABLE), counter("/ { count = total; }", "/ { alarm = reset; }"));
		assertEquals(List.of("Counter.arc:14 " + ArcIssueCodes.PORT_NOT_READABLE), counter("/ { count = total; }", "/ { total = count; }"));
		assertEquals(List.of("Counter.arc:7 " + ArcIssueCodes.PORT_NOT_READABLE), counter("var int total = 0;", "var int total = tick;"));
	}

	@Test
	void guardsAndActionsNameMembersOfTheirComponent() {
		assertEquals(List.of("Counter.arc:14 " + ArcIssueCodes.UNKNOWN_NAME), counter("/ { count = total; }", "/ { count = totl; }"));
		assertEquals(List.of("Counter.arc:14 " + ArcIssueCodes.UNKNOWN_PORT), counter("Full -> Full on tick", "Full -> Full on tock"));
	}

	@Test
	void aTriggerIsAnIncomingPort() {
		assertEquals(List.of("Counter.arc:14 " + ArcIssueCodes.DIRECTION_MISMATCH), counter("Full -> Full on tick", "Full -> Full on count"));
	}

	@Test
	void aComposedComponentHasNoAutomaton() {
		assertEquals(List.of("System.arc:13 " + ArcIssueCodes.AUTOMATON_IN_COMPOSED),
				found(SYSTEM.replace("  faults -> sink.fault;\n", "  faults -> sink.fault;\n  automaton { initial state S; }\n")));
	}

	private static final String BUFFER = """
			package demo;
			component Buffer<T>(int size) {
			  port in T in;
			  port out T out;
			}
			""";
	private static final String PIPE = """
			package demo;
			component Pipe {
			  port in Integer in;
			  port out Integer out;
			  Buffer<Integer> first(2);
			  Buffer<Integer> second(3);
			  in -> first.in;
			  first.out -> second.in;
			  second.out -> out;
			}
			""";

	@Test
	void genericComponentsTakeTypeArguments() {
		assertEquals(List.of(), ArcModelSet.of(Map.of("Buffer.arc", BUFFER, "Pipe.arc", PIPE)).issues());
		assertEquals(List.of("Pipe.arc:5 " + ArcIssueCodes.TYPE_ARGUMENT_COUNT), ArcModelSet.of(Map.of("Buffer.arc", BUFFER,
				"Pipe.arc", PIPE.replace("Buffer<Integer> first(2);", "Buffer first(2);"))).issues().stream().filter(ArcModelSet.Found::error)
				.map(f -> f.file() + ":" + f.line() + " " + f.code()).toList());
		assertEquals(List.of("Pipe.arc:6 " + ArcIssueCodes.TYPE_ARGUMENT_COUNT), ArcModelSet.of(Map.of("Buffer.arc", BUFFER,
				"Pipe.arc", PIPE.replace("Buffer<Integer> second(3);", "Buffer<Integer, String> second(3);"))).issues().stream()
				.filter(ArcModelSet.Found::error).map(f -> f.file() + ":" + f.line() + " " + f.code()).toList());
	}

	@Test
	void typeArgumentsAreReferenceTypes() {
		assertEquals(List.of("Pipe.arc:5 " + ArcIssueCodes.PRIMITIVE_TYPE_ARGUMENT),
				ArcModelSet.of(Map.of("Buffer.arc", BUFFER, "Pipe.arc", PIPE.replace("Buffer<Integer> first(2);", "Buffer<int> first(2);")))
						.issues().stream().filter(ArcModelSet.Found::error).map(f -> f.file() + ":" + f.line() + " " + f.code()).toList());
	}

	@Test
	void typeArgumentsTypeTheSubcomponentsPorts() {
		assertEquals(List.of("Pipe.arc:8 " + ArcIssueCodes.TYPE_MISMATCH, "Pipe.arc:9 " + ArcIssueCodes.TYPE_MISMATCH), ArcModelSet.of(Map.of("Buffer.arc", BUFFER,
				"Pipe.arc", PIPE.replace("Buffer<Integer> second(3);", "Buffer<String> second(3);"))).issues().stream()
				.filter(ArcModelSet.Found::error).map(f -> f.file() + ":" + f.line() + " " + f.code()).toList());
	}

	@Test
	void unknownComponentType() {
		assertEquals(List.of("System.arc:6 " + ArcIssueCodes.UNKNOWN_COMPONENT),
				found(SYSTEM.replace("  Sensor sensor;", "  Sensr sensor;")));
	}

	@Test
	void componentOfAnotherPackageNeedsImportOrQualifiedName() {
		assertEquals(List.of("System.arc:8 " + ArcIssueCodes.UNKNOWN_COMPONENT), found(SYSTEM.replace("import other.Sink;\n", "\n")));
		assertEquals(List.of(), found(SYSTEM.replace("import other.Sink;\n", "\n").replace("  Sink sink;", "  other.Sink sink;")));
		assertEquals(List.of(), found(SYSTEM.replace("import other.Sink;\n", "import other.*;\n")));
	}

	@Test
	void unknownPortOfSubcomponent() {
		assertEquals(List.of("System.arc:10 " + ArcIssueCodes.UNKNOWN_PORT), found(system("tick -> sensor.tik;")));
	}

	@Test
	void unknownOwnPort() {
		assertEquals(List.of("System.arc:10 " + ArcIssueCodes.UNKNOWN_PORT), found(system("tack -> sensor.tick;")));
	}

	@Test
	void unknownSubcomponent() {
		assertEquals(List.of("System.arc:10 " + ArcIssueCodes.UNKNOWN_SUBCOMPONENT), found(system("tick -> sensr.tick;")));
	}

	@Test
	void sourceMustBeOwnInPortOrSubcomponentOutPort() {
		// sink.in then has a second sender on line 11
		assertEquals(List.of("System.arc:10 " + ArcIssueCodes.DIRECTION_MISMATCH, "System.arc:11 " + ArcIssueCodes.TWO_SENDERS),
				found(system("filter.raw -> sink.in;")));
	}

	@Test
	void targetMustBeOwnOutPortOrSubcomponentInPort() {
		assertEquals(List.of("System.arc:10 " + ArcIssueCodes.DIRECTION_MISMATCH), found(system("tick -> sensor.tick, tick;")));
	}

	@Test
	void connectedTypesMustBeAssignable() {
		assertEquals(List.of("System.arc:10 " + ArcIssueCodes.TYPE_MISMATCH, "System.arc:10 " + ArcIssueCodes.TWO_SENDERS),
				found(system("tick -> sensor.tick, filter.raw;")));
		assertEquals(List.of("System.arc:10 " + ArcIssueCodes.TYPE_MISMATCH), found(system("tick -> sensor.tick, sink.fault;")
				.replace("  faults -> sink.fault;\n", "")));
	}

	@Test
	void aPortHasOneSender() {
		assertEquals(List.of("System.arc:11 " + ArcIssueCodes.TWO_SENDERS),
				found(SYSTEM.replace("  tick -> sensor.tick;\n", "  tick -> sensor.tick;\n  tick -> sensor.tick;\n")));
	}

	@Test
	void atomicComponentHasNoConnectors() {
		assertEquals(List.of("Sensor.arc:5 " + ArcIssueCodes.CONNECTOR_IN_ATOMIC),
				found(Map.of("Sensor.arc", SENSOR.replace("  port out Double value;\n", "  port out Double value;\n  tick -> value;\n"))));
	}

	@Test
	void automatonNeedsAnInitialState() {
		assertEquals(List.of("Filter.arc:5 " + ArcIssueCodes.NO_INITIAL_STATE),
				found(Map.of("Filter.arc", FILTER.replace("initial state Idle;", "state Idle;"))));
	}

	@Test
	void automatonHasOneInitialState() {
		assertEquals(List.of("Filter.arc:7 " + ArcIssueCodes.MULTIPLE_INITIAL_STATES),
				found(Map.of("Filter.arc", FILTER.replace("    state Busy;", "    initial state Busy;"))));
	}

	@Test
	void componentHasOneAutomaton() {
		assertEquals(List.of("Filter.arc:11 " + ArcIssueCodes.MULTIPLE_AUTOMATA),
				found(Map.of("Filter.arc", FILTER.replace("  }\n}", "  }\n  automaton { initial state X; }\n}"))));
	}

	@Test
	void transitionNamesDeclaredStates() {
		assertEquals(List.of("Filter.arc:9 " + ArcIssueCodes.UNKNOWN_STATE),
				found(Map.of("Filter.arc", FILTER.replace("Busy -> Idle;", "Busy -> Idel;"))));
	}

	@Test
	void componentsMustNotContainThemselves() {
		String a = "package demo;\ncomponent A {\n  B b;\n}\n";
		String b = "package demo;\ncomponent B {\n  port in int x;\n  A a;\n}\n";
		assertEquals(List.of("A.arc:3 " + ArcIssueCodes.INSTANTIATION_CYCLE, "B.arc:4 " + ArcIssueCodes.INSTANTIATION_CYCLE),
				ArcModelSet.of(new LinkedHashMap<>(Map.of("A.arc", a, "B.arc", b))).issues().stream().filter(ArcModelSet.Found::error)
						.map(f -> f.file() + ":" + f.line() + " " + f.code()).sorted().toList());
		assertEquals(List.of("Self.arc:3 " + ArcIssueCodes.INSTANTIATION_CYCLE),
				found(Map.of("Self.arc", "package demo;\ncomponent Self {\n  Self inner;\n}\n")));
	}

	@Test
	void namesInAComponentAreUnique() {
		assertEquals(List.of("System.arc:9 " + ArcIssueCodes.DUPLICATE_NAME),
				found(SYSTEM.replace("  Sink sink;\n", "  Sink sink;\n  Sensor tick;\n")));
		assertEquals(List.of("Sensor.arc:4 " + ArcIssueCodes.DUPLICATE_NAME),
				found(Map.of("Sensor.arc", SENSOR.replace("port out Double value;", "port out Double value, tick;"))));
	}

	@Test
	void stateNamesAreUnique() {
		assertEquals(List.of("Filter.arc:8 " + ArcIssueCodes.DUPLICATE_NAME),
				found(Map.of("Filter.arc", FILTER.replace("    state Busy;", "    state Busy;\n    state Idle;"))));
	}

	@Test
	void componentNamesAreUniqueInTheirPackage() {
		List<String> found = found(Map.of("Sensor2.arc", SENSOR));
		assertEquals(List.of("Sensor.arc:2 " + ArcIssueCodes.DUPLICATE_NAME, "Sensor2.arc:2 " + ArcIssueCodes.DUPLICATE_NAME),
				found.stream().filter(s -> s.startsWith("Sensor")).sorted().toList());
	}

	@Test
	void argumentsMatchConfigurationParameters() {
		assertEquals(List.of("System.arc:7 " + ArcIssueCodes.ARGUMENT_COUNT), found(SYSTEM.replace("Filter filter(2.0);", "Filter filter;")));
		assertEquals(List.of("System.arc:6 " + ArcIssueCodes.ARGUMENT_COUNT), found(SYSTEM.replace("Sensor sensor;", "Sensor sensor(1, f(2, 3));")));
	}

	@Test
	void unconnectedPortsAreWarned() {
		assertEquals(List.of("System.arc:6 " + ArcIssueCodes.UNCONNECTED_PORT), warnings(system("")));
		assertEquals(List.of("System.arc:5 " + ArcIssueCodes.UNCONNECTED_PORT),
				warnings(SYSTEM.replace("filter.smooth -> out, sink.in;", "filter.smooth -> sink.in;")));
		assertEquals(List.of(), found(system("")), "a warning, not an error");
	}

	@Test
	void syntaxErrorsHaveTheSyntaxCode() {
		assertEquals(List.of("System.arc:10 " + CommonIssueCodes.SYNTAX), found(system("tick -> ;")));
	}

	// MontiArc 7's constructs: data types from a class diagram, mixed port lists with stereotypes, generic bounds,
	// default parameters, fields, initial actions, hierarchical states with entry/exit, compute, inheritance, multi-instance.
	private static final String TYPES = """
			package demo;
			classdiagram Types {
			  public enum Cmd { GO, HALT; }
			}
			""";
	private static final String GATE = """
			package demo;
			import demo.Types.*;
			component Gate<T extends Number>(int limit, int offset = 0) {
			  port <<sync>> in T x, <<sync>> in Cmd cmd,
			       <<sync, delayed>> out Integer y;
			  int count = 0;
			  <<sync>> automaton {
			    initial { y = 0; } state Closed {
			      entry / { count = count + 1; }
			      exit / { count = count - 1; }
			      initial state Waiting;
			      state Ready;
			      Waiting -> Ready [cmd == Cmd.GO];
			    };
			    state Open;
			    Ready -> Open [x.intValue() > limit] / { y = Math.max(limit, offset); };
			    Open -> Closed [cmd == Cmd.HALT];
			  }
			}
			""";
	private static final String PASS = """
			package demo;
			component Pass {
			  port <<sync>> in Integer i;
			  port <<sync>> out Integer o;
			  compute {
			    int v = i == null ? 0 : i;
			    if (v > 3) {
			      o = v << 1;
			    } else {
			      switch (v) {
			        case 1: { o = 10; break; }
			        default: { o = v; break; }
			      }
			    }
			  }
			}
			""";
	/** Line 6: the subcomponents; line 7 onwards: connectors. */
	private static final String RING = """
			package demo;
			component Ring {
			  port <<sync>> in demo.Types.Cmd cmd,
			       <<sync>> out Integer out;
			  Pass p, q;
			  Gate<Integer> g(1), h(2, 3);
			  p.o -> q.i;
			  q.o -> g.x, out;
			  g.y -> p.i;
			  cmd -> g.cmd, h.cmd;
			  p.o -> h.x;
			}
			""";
	private static final String WIDE = """
			package demo;
			component Wide(int l) extends Gate<Integer>(l) {
			}
			""";

	private static List<String> montiArc(Map<String, String> replaced) {
		Map<String, String> files = new LinkedHashMap<>();
		files.put("Types.cd", TYPES);
		files.put("Gate.arc", GATE);
		files.put("Pass.arc", PASS);
		files.put("Ring.arc", RING);
		files.put("Wide.arc", WIDE);
		files.putAll(replaced);
		return ArcModelSet.of(files).issues().stream().filter(ArcModelSet.Found::error).map(f -> f.file() + ":" + f.line() + " " + f.code()).toList();
	}

	@Test
	void montiArcConstructsCheckClean() {
		assertEquals(List.of(), montiArc(Map.of()));
	}

	@Test
	void inheritanceHasNoCycles() {
		assertEquals(List.of("Wide.arc:2 " + ArcIssueCodes.INHERITANCE_CYCLE, "Wider.arc:2 " + ArcIssueCodes.INHERITANCE_CYCLE),
				montiArc(Map.of("Wide.arc", "package demo;\ncomponent Wide extends Wider {\n}\n", "Wider.arc",
						"package demo;\ncomponent Wider extends Wide {\n}\n")).stream().sorted().toList());
	}

	@Test
	void parentArgumentsMatchItsParameters() {
		assertEquals(List.of("Wide.arc:2 " + ArcIssueCodes.ARGUMENT_COUNT), montiArc(Map.of("Wide.arc", WIDE.replace("(l) {", "(l, 1, 2) {"))));
	}

	@Test
	void onlyOutgoingPortsAreDelayed() {
		assertEquals(List.of("Pass.arc:3 " + ArcIssueCodes.DELAYED_IN_PORT),
				montiArc(Map.of("Pass.arc", PASS.replace("port <<sync>> in Integer i;", "port <<delayed>> in Integer i;"))));
	}

	@Test
	void aPortHasOneTiming() {
		assertEquals(List.of("Pass.arc:3 " + ArcIssueCodes.MULTIPLE_TIMINGS),
				montiArc(Map.of("Pass.arc", PASS.replace("port <<sync>> in Integer i;", "port <<sync, timed>> in Integer i;"))));
	}

	@Test
	void feedbackLoopsNeedADelayedPort() {
		assertEquals(List.of("Ring.arc:5 " + ArcIssueCodes.FEEDBACK_WITHOUT_DELAY),
				montiArc(Map.of("Ring.arc", RING.replace("  g.y -> p.i;\n", "  q.o -> p.i;\n").replace("q.o -> g.x, out;", "g.y -> g.x;\n  h.y -> out;")
						.replace("  cmd -> g.cmd, h.cmd;\n  p.o -> h.x;\n", "  cmd -> g.cmd, h.cmd;\n  p.o -> h.x;\n"))));
	}

	@Test
	void parametersWithDefaultsComeLast() {
		assertEquals(List.of("Gate.arc:3 " + ArcIssueCodes.OPTIONAL_PARAMETER_ORDER),
				montiArc(Map.of("Gate.arc", GATE.replace("(int limit, int offset = 0)", "(int limit = 1, int offset)"))));
	}

	@Test
	void typeArgumentsAreWithinTheirBounds() {
		// both instances of the declaration take String: beyond the bound, and their ports then take String
		assertEquals(List.of("Ring.arc:11 " + ArcIssueCodes.TYPE_MISMATCH, "Ring.arc:6 " + ArcIssueCodes.TYPE_BOUND),
				montiArc(Map.of("Ring.arc", RING.replace("Gate<Integer> g(1)", "Gate<String> g(1)").replace("q.o -> g.x, out;", "q.o -> out;")))
						.stream().sorted().toList());
	}

	@Test
	void qualifiedNamesInExpressionsAreKnownTypes() {
		assertEquals(List.of("Gate.arc:16 " + ArcIssueCodes.UNKNOWN_NAME),
				montiArc(Map.of("Gate.arc", GATE.replace("Math.max(limit, offset)", "Maths.max(limit, offset)"))));
	}

	@Test
	void initialActionsReadNoPort() {
		assertEquals(List.of("Gate.arc:8 " + ArcIssueCodes.PORT_NOT_READABLE),
				montiArc(Map.of("Gate.arc", GATE.replace("initial { y = 0; }", "initial { y = x.intValue(); }"))));
	}

	@Test
	void superStatesHaveAnInitialSubstate() {
		assertEquals(List.of("Gate.arc:8 " + ArcIssueCodes.NO_INITIAL_STATE),
				montiArc(Map.of("Gate.arc", GATE.replace("initial state Waiting;", "state Waiting;"))));
	}
}
