package org.triad.generator;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;

import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.dsl.app.ModelDiagnostic;
import org.triad.dsl.triad.Situation;
import org.triad.runtime.app.GeneratedObjects;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.AppSchema;

/**
 * The situations ({@code .state}) of an application, read for tests and fakes: each as a {@link State}
 * whose objects are the application's generated domain classes, ready for a dry world
 * ({@code TaskRunner.dry(schema, state)}) or for a fake robot and world to start from.
 *
 * <pre>{@code
 * Situations situations = Situations.load(Path.of("src/main/models"), HospitalSchema.class);
 * State morning = situations.state("Morning");            // or situations.state("Morning.state"): its first situation
 * Room storage = (Room) morning.object("storage").orElseThrow();
 * }</pre>
 */
public final class Situations {
	private final LoadedApplication loaded;
	private final AppSchema schema;
	private final Class<?> generatedClass;

	private Situations(LoadedApplication loaded, Class<?> generatedClass) {
		this.loaded = loaded;
		this.schema = SchemaBuilder.build(loaded.application());
		this.generatedClass = generatedClass;
	}

	/**
	 * Loads and checks the application below {@code modelsDir}; {@code generatedClass} is any class of the code
	 * generated from it (e.g. {@code HospitalSchema.class}).
	 *
	 * @throws IllegalArgumentException when the folder does not exist or the models have errors (each error as
	 *         {@code path:line:col: error CODE: message})
	 */
	public static Situations load(Path modelsDir, Class<?> generatedClass) {
		if (!Files.isDirectory(modelsDir)) {
			throw new IllegalArgumentException("not a folder of models: " + modelsDir.toAbsolutePath());
		}
		LoadedApplication loaded = ApplicationAssembler.load(modelsDir);
		if (loaded.hasErrors()) {
			throw new IllegalArgumentException("the models below " + modelsDir + " have errors:\n" + loaded.diagnostics().stream()
					.filter(ModelDiagnostic::isError).map(d -> d.format(loaded.root())).collect(Collectors.joining("\n")));
		}
		return new Situations(loaded, generatedClass);
	}

	/** The application's schema as the models say (equal to the generated {@code <App>Schema.SCHEMA}). */
	public AppSchema schema() {
		return schema;
	}

	/** The names of the application's situations, in file order. */
	public List<String> names() {
		return loaded.application().getSituations().stream().map(Situation::getName).toList();
	}

	/**
	 * The situation of this name, or for a name ending in {@code .state} the first situation of that file, with
	 * generated objects; {@code state B extends A} is A's objects and facts overridden by B's.
	 */
	public State state(String name) {
		Situation situation = find(name);
		return GeneratedObjects.typed(SituationReader.read(situation, schema), generatedClass);
	}

	private Situation find(String name) {
		for (Situation s : loaded.application().getSituations()) {
			boolean byFile = name.endsWith(".state") && Path.of(s.eResource().getURI().toFileString()).getFileName().toString()
					.equals(Path.of(name).getFileName().toString());
			if (byFile || s.getName().equals(name)) {
				return s;
			}
		}
		throw new IllegalArgumentException("no situation '" + name + "' in the application below " + loaded.root() + "; it has " + names());
	}
}
