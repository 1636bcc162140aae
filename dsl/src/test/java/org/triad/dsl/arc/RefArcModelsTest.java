package org.triad.dsl.arc;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.emf.ecore.resource.Resource;
import org.junit.jupiter.api.Test;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;

/** The reference architecture's models (refarc/src/main/arc) parse, link and validate clean through the application loader. */
class RefArcModelsTest {

	@Test
	void refarcModelsHaveNoDiagnostics() {
		LoadedApplication app = ApplicationAssembler.load(Path.of("..", "refarc", "src", "main", "arc"));
		String printed = app.diagnostics().stream().map(d -> d.format(app.root())).collect(Collectors.joining("\n"));
		assertEquals("", printed);
		List<String> components = app.resourceSet().getResources().stream().map(Resource::getContents)
				.filter(c -> !c.isEmpty() && c.get(0) instanceof ArcModel)
				.map(c -> ((ArcModel) c.get(0)).getComponent())
				.map(c -> c.getName() + (org.triad.dsl.semantics.ArcModels.subcomponents(c).isEmpty() ? "" : "/" + org.triad.dsl.semantics.ArcModels.subcomponents(c).size() + "/" + c.getConnectors().size()))
				.sorted().toList();
		assertEquals(List.of("ActionExecutor", "Controller", "OpenRefArc/4/12", "PlanVerifier", "Planner", "RefArc/4/11", "RemoteOperator",
				"StateProvider"), components);
	}
}
