package org.triad.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.cli.TriadCliTest.Run;

/** {@code triad arc DIR --svg OUT}: RefArc and the hospital's architecture drawn by Graphviz. */
class ArcCommandTest {
	@TempDir
	Path out;

	@Test
	void refArcIsDrawnWithItsPartsPortsAndConnectors() throws Exception {
		Run run = TriadCliTest.run("arc", "../refarc/src/main/arc", "--svg", out.toString(), "--component", "RefArc");
		assertEquals(0, run.exit(), run.out() + run.err());
		assertEquals("drew org.triad.refarc.RefArc into " + out.resolve("RefArc.svg"), run.out().strip());
		String svg = Files.readString(out.resolve("RefArc.svg"));
		assertTrue(svg.startsWith("<?xml") && svg.contains("<svg"), svg);
		for (String text : new String[] { "controller : Controller", "planner : Planner", "stateProvider : StateProvider",
				"actionExecutor : ActionExecutor", "planRequest", "actionResult", "TaskInstance", "faults" }) {
			assertTrue(svg.contains(text), text + " is drawn");
		}
		// 11 connectors, one arrow each
		assertEquals(11, svg.split("class=\"edge\"", -1).length - 1);
	}

	@Test
	void theControllersAutomatonIsDrawn() throws Exception {
		Run run = TriadCliTest.run("arc", "../refarc/src/main/arc", "--svg", out.toString(), "--component", "org.triad.refarc.Controller");
		assertEquals(0, run.exit(), run.out() + run.err());
		String svg = Files.readString(out.resolve("Controller.svg"));
		for (String text : new String[] { "Idle", "Planning", "Executing", "on task", "failures &lt; maxReplans" }) {
			assertTrue(svg.contains(text), text + " is drawn");
		}
	}

	@Test
	void theHospitalsArchitectureLinksAgainstRefArc() throws Exception {
		Run run = TriadCliTest.run("arc", "../models/hospital/src/main/arc", "--svg", out.toString());
		assertEquals(0, run.exit(), run.out() + run.err());
		String svg = Files.readString(out.resolve("VerifiedHospital.svg"));
		for (String text : new String[] { "core : OpenRefArc", "verifier : PlanVerifier", "operator : RemoteOperator", "proposedPlan" }) {
			assertTrue(svg.contains(text), text + " is drawn");
		}
	}

	@Test
	void anUnknownComponentIsNamedWithTheOnesThereAre() {
		Run run = TriadCliTest.run("arc", "../refarc/src/main/arc", "--svg", out.toString(), "--component", "Nope");
		assertEquals(2, run.exit());
		assertTrue(run.err().startsWith("triad arc: no component 'Nope' below ../refarc/src/main/arc; there are [ActionExecutor, Controller,"),
				run.err());
	}
}
