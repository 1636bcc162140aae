package org.triad.dsl.app;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.IResourceValidator;
import org.eclipse.xtext.validation.Issue;
import org.triad.dsl.TriadLanguages;
import org.triad.dsl.arc.ArcModel;
import org.triad.dsl.triad.Actor;
import org.triad.dsl.triad.ActorKind;
import org.triad.dsl.triad.ActorModel;
import org.triad.dsl.triad.Application;
import org.triad.dsl.triad.ClassDiagram;
import org.triad.dsl.triad.GoalModel;
import org.triad.dsl.triad.StateModel;
import org.triad.dsl.triad.TaskModel;
import org.triad.dsl.triad.TriadFactory;
import org.triad.dsl.validation.CommonIssueCodes;

import com.google.inject.Injector;

/**
 * Loads every model file below a folder into one resource set, so the files link to each other,
 * validates them all, and checks the application as a whole (one class diagram, one robot, one
 * world). Never throws for bad model content: whatever the input, problems come back as
 * diagnostics with a location.
 */
public final class ApplicationLoader {
	private ApplicationLoader() {
	}

	public static LoadedApplication load(Path root) {
		return load(root, List.of());
	}

	/**
	 * Loads the models below {@code root}, linked with the models below {@code libraries} (e.g. the
	 * reference architecture's components), which are neither checked nor part of the application.
	 */
	public static LoadedApplication load(Path root, List<Path> libraries) {
		Path dir = root.toAbsolutePath().normalize();
		List<Path> files = modelFiles(dir);
		Injector injector = TriadLanguages.anyInjector();
		XtextResourceSet resourceSet = injector.getInstance(XtextResourceSet.class);
		List<ModelDiagnostic> diagnostics = new ArrayList<>();
		List<Resource> resources = new ArrayList<>();
		for (Path library : libraries) {
			for (Path file : modelFiles(library.toAbsolutePath().normalize())) {
				resourceSet.getResource(URI.createFileURI(file.toString()), true);
			}
		}
		for (Path file : files) {
			try {
				resources.add(resourceSet.getResource(URI.createFileURI(file.toString()), true));
			} catch (RuntimeException e) {
				diagnostics.add(new ModelDiagnostic(file, 1, 1, ModelDiagnostic.Severity.ERROR, CommonIssueCodes.SYNTAX,
						"cannot read the file: " + rootMessage(e)));
			}
		}
		EcoreUtil.resolveAll(resourceSet);
		for (Resource r : resources) {
			diagnostics.addAll(validate(r));
		}
		Application application = assemble(dir, resources, diagnostics);
		Collections.sort(diagnostics);
		return new LoadedApplication(dir, resourceSet, application, List.copyOf(diagnostics));
	}

	/** The model files below a folder, in a stable order; hidden folders and build output are skipped. */
	public static List<Path> modelFiles(Path dir) {
		try (Stream<Path> walk = Files.walk(dir)) {
			return walk.filter(Files::isRegularFile)
					.filter(p -> TriadLanguages.EXTENSIONS.contains(extension(p)))
					.filter(p -> !isSkipped(dir.relativize(p)))
					.sorted()
					.toList();
		} catch (IOException e) {
			throw new UncheckedIOException("cannot list model files below " + dir + ": " + e.getMessage(), e);
		}
	}

	private static boolean isSkipped(Path relative) {
		for (Path part : relative) {
			String s = part.toString();
			if (s.startsWith(".") || s.equals("target") || s.equals("node_modules")) {
				return true;
			}
		}
		return false;
	}

	static String extension(Path p) {
		String name = p.getFileName().toString();
		int dot = name.lastIndexOf('.');
		return dot < 0 ? "" : name.substring(dot + 1);
	}

	private static List<ModelDiagnostic> validate(Resource resource) {
		Path file = Path.of(resource.getURI().toFileString());
		List<ModelDiagnostic> result = new ArrayList<>();
		try {
			IResourceValidator validator = ((XtextResource) resource).getResourceServiceProvider().getResourceValidator();
			for (Issue issue : validator.validate(resource, CheckMode.ALL, CancelIndicator.NullImpl)) {
				if (issue.getSeverity() == Severity.INFO) {
					continue;
				}
				result.add(new ModelDiagnostic(file, orOne(issue.getLineNumber()), orOne(issue.getColumn()),
						issue.getSeverity() == Severity.ERROR ? ModelDiagnostic.Severity.ERROR : ModelDiagnostic.Severity.WARNING,
						issue.getCode() == null ? CommonIssueCodes.SYNTAX : issue.getCode(), oneLine(issue.getMessage())));
			}
		} catch (RuntimeException e) {
			result.add(new ModelDiagnostic(file, 1, 1, ModelDiagnostic.Severity.ERROR, CommonIssueCodes.SYNTAX,
					"cannot check the file: " + rootMessage(e)));
		}
		return result;
	}

	private static Application assemble(Path dir, List<Resource> resources, List<ModelDiagnostic> diagnostics) {
		Application app = TriadFactory.eINSTANCE.createApplication();
		app.setName(dir.getFileName() == null ? "application" : dir.getFileName().toString());
		List<ClassDiagram> diagrams = new ArrayList<>();
		List<Actor> robots = new ArrayList<>();
		List<Actor> worlds = new ArrayList<>();
		for (Resource r : resources) {
			for (EObject root : r.getContents()) {
				if (root instanceof ClassDiagram cd) {
					diagrams.add(cd);
				} else if (root instanceof ActorModel m && m.getActor() != null) {
					(m.getActor().getKind() == ActorKind.ROBOT ? robots : worlds).add(m.getActor());
				} else if (root instanceof GoalModel m) {
					app.getGoals().addAll(m.getGoals());
				} else if (root instanceof TaskModel m) {
					app.getTasks().addAll(m.getTasks());
				} else if (root instanceof StateModel m) {
					app.getSituations().addAll(m.getSituations());
				}
			}
		}
		if (!diagrams.isEmpty()) {
			app.setDomain(diagrams.get(0));
			app.setName(diagrams.get(0).getName());
		}
		if (!robots.isEmpty()) {
			app.setRobot(robots.get(0));
		}
		if (!worlds.isEmpty()) {
			app.setWorld(worlds.get(0));
		}
		if (resources.stream().allMatch(ApplicationLoader::isArchitecture)) {
			return app; // no application models (at most .arc files): nothing to require of an application
		}
		EObject anchor = diagrams.isEmpty()
				? resources.stream().filter(r -> !isArchitecture(r)).flatMap(r -> r.getContents().stream()).findFirst().orElse(null)
				: diagrams.get(0);
		Path anchorFile = anchor == null ? dir : Path.of(anchor.eResource().getURI().toFileString());
		int line = anchor == null ? 1 : lineOf(anchor);
		if (diagrams.isEmpty()) {
			diagnostics.add(structure(anchorFile, line, "the application has no class diagram (a .cd file with 'classdiagram Name { ... }')"));
		}
		if (diagrams.size() > 1) {
			for (ClassDiagram extra : diagrams.subList(1, diagrams.size())) {
				diagnostics.add(structure(Path.of(extra.eResource().getURI().toFileString()), lineOf(extra),
						"the application has more than one class diagram: '" + extra.getName() + "' and '" + diagrams.get(0).getName() + "'"));
			}
		}
		if (robots.isEmpty()) {
			diagnostics.add(structure(anchorFile, line, "the application has no robot (an .actor file with 'robot Name { ... }')"));
		}
		if (worlds.isEmpty()) {
			diagnostics.add(structure(anchorFile, line, "the application has no world (an .actor file with 'world Name { ... }')"));
		}
		return app;
	}

	private static boolean isArchitecture(Resource r) {
		return r.getContents().stream().anyMatch(ArcModel.class::isInstance);
	}

	private static ModelDiagnostic structure(Path file, int line, String message) {
		return new ModelDiagnostic(file, line, 1, ModelDiagnostic.Severity.ERROR, CommonIssueCodes.APPLICATION_STRUCTURE, message);
	}

	private static int lineOf(EObject e) {
		ICompositeNode node = NodeModelUtils.getNode(e);
		return node == null ? 1 : node.getStartLine();
	}

	private static int orOne(Integer i) {
		return i == null || i < 1 ? 1 : i;
	}

	private static String oneLine(String s) {
		return s == null ? "" : s.replace('\n', ' ').replace('\r', ' ');
	}

	private static String rootMessage(Throwable e) {
		Throwable t = e;
		while (t.getCause() != null && t.getCause() != t) {
			t = t.getCause();
		}
		return t.getMessage() == null ? t.getClass().getSimpleName() : t.getMessage();
	}

}
