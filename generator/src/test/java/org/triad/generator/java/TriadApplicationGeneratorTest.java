package org.triad.generator.java;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.generator.GeneratorContext;
import org.eclipse.xtext.generator.IFileSystemAccess;
import org.eclipse.xtext.generator.IGenerator2;
import org.eclipse.xtext.generator.InMemoryFileSystemAccess;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.dsl.triad.ClassDiagram;

/** The Xtext entry used by the xtext-maven-plugin generates what the Java API generates. */
class TriadApplicationGeneratorTest {
	@Test
	void classDiagramResourceGeneratesTheWholeApplication() {
		LoadedApplication loaded = ApplicationAssembler.load(Path.of("../models/hospital/src/main/models"));
		Resource cd = loaded.application().getDomain().eResource();
		InMemoryFileSystemAccess fsa = new InMemoryFileSystemAccess();
		new TriadApplicationGenerator().doGenerate(cd, fsa, new GeneratorContext());

		Map<String, String> expected = new TreeMap<>();
		for (TriadJavaGenerator.GeneratedFile f : TriadJavaGenerator.files(loaded.application(), "generated.hospital")) {
			expected.put(IFileSystemAccess.DEFAULT_OUTPUT + f.relativePath().toString().replace('\\', '/'), f.content());
		}
		Map<String, String> generated = new TreeMap<>();
		fsa.getAllFiles().forEach((k, v) -> generated.put(k, v.toString()));
		assertEquals(expected, generated);
		assertTrue(generated.containsKey(IFileSystemAccess.DEFAULT_OUTPUT + "generated/hospital/IRobot.java"));
	}

	@Test
	void otherModelsGenerateNothingOnTheirOwn() {
		LoadedApplication loaded = ApplicationAssembler.load(Path.of("../models/logistics/src/main/models"));
		InMemoryFileSystemAccess fsa = new InMemoryFileSystemAccess();
		for (Resource r : loaded.resourceSet().getResources()) {
			if (!(r.getContents().get(0) instanceof ClassDiagram)) {
				new TriadApplicationGenerator().doGenerate(r, fsa, new GeneratorContext());
			}
		}
		assertEquals(Map.of(), fsa.getAllFiles());
	}

	@Test
	void anApplicationWithTwoRobotsGeneratesNothingAndIsReportedOnBothRobots(@TempDir Path dir) throws IOException {
		Path models = Path.of("../models/logistics/src/main/models");
		try (var files = Files.list(models)) {
			for (Path f : files.toList()) {
				Files.copy(f, dir.resolve(f.getFileName()));
			}
		}
		Files.writeString(dir.resolve("Spare.actor"), "domain LogisticsDomain;\nrobot Spare {\n  property WayPoint loc();\n}\n");
		LoadedApplication loaded = ApplicationAssembler.load(dir);
		assertEquals(List.of("LogisticsRobot.actor:3:7: error actor.duplicate-kind: an application has one robot, but 'Spare' in Spare.actor is one too",
				"Spare.actor:2:7: error actor.duplicate-kind: an application has one robot, but 'LogisticsRobot' in LogisticsRobot.actor is one too"),
				loaded.diagnostics().stream().map(d -> d.format(loaded.root())).toList());
		Resource cd = loaded.application().getDomain().eResource();
		InMemoryFileSystemAccess fsa = new InMemoryFileSystemAccess();
		new TriadApplicationGenerator().doGenerate(cd, fsa, new GeneratorContext());
		assertEquals(Map.of(), fsa.getAllFiles());
	}

	@Test
	void setupBindsTheGenerator() {
		IGenerator2 generator = new TriadJavaGeneratorSetup().createInjector().getInstance(IGenerator2.class);
		assertTrue(generator instanceof TriadApplicationGenerator, generator.getClass().getName());
	}
}
