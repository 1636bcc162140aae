package org.triad.dsl.arc;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
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
			    Idle -> Busy [raw > 0.5 && gain != 0] / { smooth = raw * gain; };
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
	void opaqueGuardAndActionKeepTheirText() {
		ArcModel filter = ArcModelSet.of("Filter.arc", FILTER).model("Filter.arc");
		Transition t = filter.getComponent().getAutomata().get(0).getTransitions().get(0);
		assertEquals("raw > 0.5 && gain != 0", t.getGuard());
		assertEquals("smooth = raw * gain;", t.getAction());
		assertEquals(List.of("raw", "smooth"), ArcModels.ports(filter.getComponent()).stream().map(ArcPort::getName).toList());
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
}
