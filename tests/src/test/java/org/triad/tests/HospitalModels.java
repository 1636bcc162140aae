package org.triad.tests;

import java.nio.file.Path;

import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.generator.SchemaBuilder;
import org.triad.generator.SituationReader;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.AppSchema;

/** The hospital example application as the tests read it: its schema and its situations. */
final class HospitalModels {
	static final Path FOLDER = Path.of("..", "models", "hospital", "src", "main", "models");

	final AppSchema schema;
	private final LoadedApplication loaded;

	private HospitalModels(LoadedApplication loaded) {
		this.loaded = loaded;
		this.schema = SchemaBuilder.build(loaded.application());
	}

	/** Loads the models; they must be free of errors. */
	static HospitalModels load() {
		LoadedApplication app = ApplicationAssembler.load(FOLDER);
		if (app.hasErrors()) {
			throw new AssertionError("the hospital models have errors: " + app.diagnostics());
		}
		return new HospitalModels(app);
	}

	/** The situation of that name, as a state. */
	State situation(String name) {
		return SituationReader.read(loaded.application().getSituations().stream().filter(s -> s.getName().equals(name)).findFirst()
				.orElseThrow(() -> new AssertionError("no situation " + name)), schema);
	}
}
