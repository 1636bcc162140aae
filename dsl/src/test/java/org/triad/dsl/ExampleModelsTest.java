package org.triad.dsl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.nio.file.Path;
import java.util.stream.Collectors;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.dsl.app.ModelDiagnostic;

/** The example applications shipped in models/ are clean: no error, no warning. */
class ExampleModelsTest {

	@ParameterizedTest
	@ValueSource(strings = { "logistics", "hospital" })
	void exampleApplicationHasNoDiagnostics(String name) {
		Path dir = Path.of("..", "models", name, "src", "main", "models");
		LoadedApplication app = ApplicationAssembler.load(dir);
		String printed = app.diagnostics().stream().map(d -> d.format(app.root())).collect(Collectors.joining("\n"));
		assertEquals("", printed);
		assertNotNull(app.application().getRobot());
		assertNotNull(app.application().getWorld());
		assertNotNull(app.application().getDomain());
	}
}
