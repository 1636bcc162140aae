package org.triad.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.triad.cli.TriadCli;

/**
 * {@code triad demo} launches the hospital application's own demo in a child JVM on that
 * application's class path (the CLI does not depend on the example): its options, output and exit
 * code pass through. The delivery itself is tested in models/hospital (HospitalDemoTest).
 */
class DemoLaunchTest {
	private String home;

	@BeforeEach
	void triadHomeIsTheCheckout() {
		home = System.getProperty("triad.home");
		System.setProperty("triad.home", "..");
	}

	@AfterEach
	void restore() {
		if (home == null) {
			System.clearProperty("triad.home");
		} else {
			System.setProperty("triad.home", home);
		}
	}

	@Test
	void theDemosOwnHelpIsPrinted() {
		StringWriter out = new StringWriter();
		StringWriter err = new StringWriter();
		int code = TriadCli.execute(new String[] { "demo", "--help" }, new PrintWriter(out, true), new PrintWriter(err, true));
		assertEquals(0, code, out + err.toString());
		assertTrue(out.toString().startsWith("Usage: triad demo"), out::toString);
		assertTrue(out.toString().contains("--close-fire-door-at=SECONDS"), out::toString);
	}

	@Test
	void aBadOptionIsTheDemosOneLineErrorWithExitCode2() {
		StringWriter out = new StringWriter();
		StringWriter err = new StringWriter();
		int code = TriadCli.execute(new String[] { "demo", "--close-fire-door-at", "-5" }, new PrintWriter(out, true), new PrintWriter(err, true));
		assertEquals(2, code);
		assertEquals("triad demo: --close-fire-door-at takes a time in seconds >= 0, not -5.0", err.toString().strip());
		assertEquals("", out.toString());
	}
}
