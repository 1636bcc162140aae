package org.triad.cli;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;

import org.eclipse.emf.ecore.resource.Resource;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.dsl.app.ModelDiagnostic;
import org.triad.dsl.arc.ArcModel;
import org.triad.dsl.arc.ComponentType;
import org.triad.dsl.semantics.ArcModels;
import org.triad.generator.arc.ArcDiagram;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code triad arc DIR --svg OUT}: pictures of the architecture models below DIR, drawn by Graphviz. */
@Command(name = "arc", mixinStandardHelpOptions = true,
		description = { "Draw the components of the architecture models (.arc) below DIR as SVG pictures with Graphviz's dot:",
				"ports, subcomponents and connectors; an atomic component's automaton. RefArc's models are linked when needed.",
				"Exit code: 0 drawn, 1 model errors (printed as path:line:col: error CODE: message), 2 bad input or no Graphviz." })
public final class ArcCommand implements Callable<Integer> {
	private static final String DOT = "dot";

	@Parameters(index = "0", paramLabel = "DIR", description = "a folder of .arc models")
	private Path dir;

	@Option(names = "--svg", required = true, paramLabel = "OUT", description = "the folder to write one COMPONENT.svg per component to")
	private Path out;

	@Option(names = "--component", paramLabel = "NAME", description = "draw only this component (simple or qualified name)")
	private String only;

	@CommandLine.Spec
	private CommandLine.Model.CommandSpec spec;

	@Override
	public Integer call() throws Exception {
		if (!Files.isDirectory(dir)) {
			throw new ModelSession.UserError("not a folder: " + dir);
		}
		OutputFolder.check(out, "--svg");
		LoadedApplication app = ApplicationAssembler.load(dir);
		for (ModelDiagnostic d : app.diagnostics()) {
			spec.commandLine().getOut().println(d.format(app.root()));
		}
		if (app.hasErrors()) {
			return 1;
		}
		List<ComponentType> components = components(app);
		List<ComponentType> drawn = components.stream()
				.filter(c -> only == null || c.getName().equals(only) || ArcModels.qualifiedName(c).equals(only)).toList();
		if (drawn.isEmpty()) {
			throw new ModelSession.UserError(only == null ? "no .arc models below " + dir
					: "no component '" + only + "' below " + dir + "; there are " + components.stream().map(ComponentType::getName).sorted().toList());
		}
		ArcDiagram diagram = new ArcDiagram();
		for (ComponentType c : drawn) {
			Files.createDirectories(out);
			Path svg = out.resolve(c.getName() + ".svg");
			render(diagram.dot(c), svg);
			spec.commandLine().getOut().println("drew " + ArcModels.qualifiedName(c) + " into " + svg);
		}
		return 0;
	}

	private static List<ComponentType> components(LoadedApplication app) {
		List<ComponentType> result = new ArrayList<>();
		for (Resource r : app.resourceSet().getResources()) {
			boolean own = r.getURI().isFile() && Path.of(r.getURI().toFileString()).toAbsolutePath().startsWith(app.root().toAbsolutePath());
			if (own && !r.getContents().isEmpty() && r.getContents().get(0) instanceof ArcModel m && m.getComponent() != null) {
				result.add(m.getComponent());
			}
		}
		result.sort((a, b) -> ArcModels.qualifiedName(a).compareTo(ArcModels.qualifiedName(b)));
		return result;
	}

	private static void render(String dot, Path svg) throws IOException, InterruptedException {
		Process p;
		try {
			p = new ProcessBuilder(DOT, "-Tsvg", "-o", svg.toString()).redirectErrorStream(true).start();
		} catch (IOException e) {
			throw new ModelSession.UserError("--svg needs Graphviz's '" + DOT + "' on PATH (Debian: apt-get install graphviz): " + e.getMessage());
		}
		try (OutputStream in = p.getOutputStream()) {
			in.write(dot.getBytes(StandardCharsets.UTF_8));
		}
		String messages;
		try (InputStream o = p.getInputStream()) {
			messages = new String(o.readAllBytes(), StandardCharsets.UTF_8).strip();
		}
		if (!p.waitFor(60, TimeUnit.SECONDS)) {
			p.destroyForcibly();
			throw new ModelSession.UserError("Graphviz's " + DOT + " did not finish drawing " + svg + " within 60 s");
		}
		if (p.exitValue() != 0) {
			throw new ModelSession.UserError("Graphviz's " + DOT + " could not draw " + svg + ": " + messages);
		}
	}

	/** A folder with RefArc's models, which travel in refarc's jar (or its classes folder in a build). */

}
