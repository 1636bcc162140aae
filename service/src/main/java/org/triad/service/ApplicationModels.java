package org.triad.service;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.dsl.app.ModelDiagnostic;
import org.triad.dsl.triad.Situation;
import org.triad.generator.SchemaBuilder;
import org.triad.generator.SituationReader;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.AppSchema;

/** The application the service runs: its models below a folder, checked, as a runtime schema with its situations. */
public final class ApplicationModels {
    private final Path dir;
    private final LoadedApplication loaded;
    private final AppSchema schema;

    private ApplicationModels(Path dir, LoadedApplication loaded) {
        this.dir = dir;
        this.loaded = loaded;
        this.schema = SchemaBuilder.build(loaded.application());
    }

    /** Loads and checks the models below {@code dir}; model errors end the start with their diagnostics. */
    public static ApplicationModels load(Path dir) {
        if (!Files.isDirectory(dir)) {
            throw ServiceError.startup("not a folder: " + dir);
        }
        LoadedApplication app = ApplicationAssembler.load(dir);
        if (app.hasErrors()) {
            StringBuilder b = new StringBuilder("the models have errors (run 'triad check " + dir + "'):");
            for (ModelDiagnostic d : app.diagnostics()) {
                if (d.isError()) {
                    b.append("\n").append(d.format(app.root()));
                }
            }
            throw ServiceError.startup(b.toString());
        }
        if (app.application().getTasks().isEmpty()) {
            throw ServiceError.startup("the models below " + dir + " define no task: the service has nothing to offer");
        }
        return new ApplicationModels(dir, app);
    }

    public Path dir() {
        return dir;
    }

    public AppSchema schema() {
        return schema;
    }

    /**
     * A situation by the name of its {@code .state} file or its own name; {@code null} is the
     * application's first situation.
     *
     * @throws IllegalArgumentException when there is none such
     */
    public State situation(String name) {
        List<Situation> all = loaded.application().getSituations();
        if (all.isEmpty()) {
            throw new IllegalArgumentException("the application has no situation (.state file)");
        }
        if (name == null) {
            return SituationReader.read(all.get(0), schema);
        }
        List<String> known = new ArrayList<>();
        for (Situation s : all) {
            String file = Path.of(s.eResource().getURI().toFileString()).getFileName().toString();
            if (s.getName().equals(name) || file.equals(name) || file.equals(name + ".state")) {
                return SituationReader.read(s, schema);
            }
            known.add(s.getName() + " (" + file + ")");
        }
        throw new IllegalArgumentException("no situation '" + name + "'; known: " + known);
    }
}
