package org.triad.fuzz;

import java.io.IOException;

import com.code_intelligence.jazzer.junit.FuzzTest;

/**
 * Each model language through {@code ./triad check}'s entry: any bytes as one file of an otherwise
 * valid application end in located findings with registered codes or a clean result, in bounded
 * time. Seeds: the example models' files and the inputs that found bugs
 * ({@code src/test/resources/org/triad/fuzz/ModelLanguagesFuzzTestInputs/<target>/}).
 */
class ModelLanguagesFuzzTest {
	@FuzzTest(maxDuration = "10m")
	void classDiagram(byte[] content) throws IOException {
		ModelCheckBoundary.check("LogisticsDomain.cd", content);
	}

	@FuzzTest(maxDuration = "10m")
	void actor(byte[] content) throws IOException {
		ModelCheckBoundary.check("LogisticsRobot.actor", content);
	}

	@FuzzTest(maxDuration = "10m")
	void goal(byte[] content) throws IOException {
		ModelCheckBoundary.check("IsAt.goal", content);
	}

	@FuzzTest(maxDuration = "10m")
	void task(byte[] content) throws IOException {
		ModelCheckBoundary.check("GoTo.task", content);
	}

	@FuzzTest(maxDuration = "10m")
	void state(byte[] content) throws IOException {
		ModelCheckBoundary.check("Floor.state", content);
	}

	@FuzzTest(maxDuration = "10m")
	void architecture(byte[] content) throws IOException {
		ModelCheckBoundary.check("Fuzzed.arc", content);
	}
}
