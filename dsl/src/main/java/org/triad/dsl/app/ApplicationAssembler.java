package org.triad.dsl.app;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.IResourceValidator;
import org.eclipse.xtext.validation.Issue;
import org.triad.dsl.TriadLanguages;
import org.triad.dsl.triad.ActorModel;
import org.triad.dsl.triad.Application;
import org.triad.dsl.triad.ClassDiagram;
import org.triad.dsl.triad.GoalModel;
import org.triad.dsl.triad.StateModel;
import org.triad.dsl.triad.TaskModel;
import org.triad.dsl.triad.TriadFactory;
import org.triad.dsl.validation.CommonIssueCodes;
import org.triad.dsl.validation.FileIssueCodes;

import com.google.inject.Injector;

/**
 * The one way a Triad application is put together from its model files, used by the command line,
 * the language server (through the validators), the Maven build ({@code xtext-maven-plugin} with the
 * generator bound in the class-diagram language) and the Gradle plugin:
 * <ul>
 * <li><b>files</b>: every {@code .cd .actor .goal .task .state .arc} file below the models folder
 * (hidden folders, {@code target} and {@code node_modules} skipped), linked in one resource set;</li>
 * <li><b>name</b>: the application is named after its class diagram ({@code classdiagram Hospital}
 * makes application {@code Hospital}, generated package {@code generated.hospital}), wherever the
 * files are;</li>
 * <li><b>actors</b>: exactly one class diagram, one robot actor and one world actor
 * ({@link ApplicationStructure}); anything else is an error {@code app.class-diagram-count},
 * {@code app.robot-count}, {@code app.world-count} or {@code actor.duplicate-kind} on the offending
 * element;</li>
 * <li><b>libraries</b>: architecture models ({@code .arc}) link against the component libraries on
 * the class path (a jar's {@code triad-models/} folder, e.g. RefArc's components in the refarc jar,
 * see {@link ModelLibraries}) and against extra library folders given by the caller.</li>
 * </ul>
 * Never throws for bad model content: whatever the input, problems come back as diagnostics with a
 * location.
 */
public final class ApplicationAssembler {
	/**
	 * The largest model file read, in bytes (2 MiB; the hospital's largest model has a few KB). Loading
	 * holds a model's syntax tree, node model and links in memory, a few hundred bytes per byte of
	 * text (cli/BENCHMARK.md, "Model size"), so this bounds what one file can cost; a larger file is
	 * refused with {@link FileIssueCodes#TOO_LARGE} at {@code path:1:1} before any of it is read.
	 */
	public static final long MAX_MODEL_FILE_BYTES = 2L << 20;

	private ApplicationAssembler() {
	}

	/** Loads, links and checks the application whose models are below {@code modelsDir}. */
	public static LoadedApplication load(Path modelsDir) {
		return load(modelsDir, List.of());
	}

	/**
	 * Loads the models below {@code root}, linked with {@code libraries} (folders of models, or jars
	 * whose {@code triad-models/} folder holds models: what a Gradle or Maven build passes from its
	 * class path) and, for architectures, the libraries on this JVM's class path. Library models are
	 * neither checked nor part of the application.
	 */
	public static LoadedApplication load(Path root, List<Path> libraries) {
		Path dir = root.toAbsolutePath().normalize();
		List<Path> files = modelFiles(dir);
		Injector injector = TriadLanguages.anyInjector();
		XtextResourceSet resourceSet = injector.getInstance(XtextResourceSet.class);
		List<ModelDiagnostic> tooLarge = tooLarge(files);
		for (Path library : libraries) {
			if (!Files.isRegularFile(library)) {
				tooLarge.addAll(tooLarge(modelFiles(library.toAbsolutePath().normalize())));
			}
		}
		if (!tooLarge.isEmpty()) {
			// nothing is read: the other files' findings would only be the missing file's consequences
			Application nothing = assemble(List.of());
			nothing.setName(dir.getFileName() == null ? "application" : dir.getFileName().toString());
			Collections.sort(tooLarge);
			return new LoadedApplication(dir, resourceSet, nothing, List.copyOf(tooLarge));
		}
		List<ModelDiagnostic> diagnostics = new ArrayList<>();
		List<Resource> resources = new ArrayList<>();
		Set<String> shadowing = new HashSet<>(relativePaths(dir, files));
		for (Path library : libraries) {
			if (Files.isRegularFile(library)) { // a jar: its triad-models/ folder
				for (URI file : ModelLibraries.inJar(library)) {
					resourceSet.getResource(file, true);
					shadowing.add(ModelLibraries.relativePath(file));
				}
				continue;
			}
			Path libraryDir = library.toAbsolutePath().normalize();
			List<Path> libraryFiles = modelFiles(libraryDir);
			for (Path file : libraryFiles) {
				resourceSet.getResource(URI.createFileURI(file.toString()), true);
			}
			shadowing.addAll(relativePaths(libraryDir, libraryFiles));
		}
		if (files.stream().anyMatch(f -> extension(f).equals("arc"))) {
			for (URI library : ModelLibraries.onClassPath()) {
				// a copy in the application or a library folder (RefArc's own build) shadows the class path's
				if (!shadowing.contains(ModelLibraries.relativePath(library))) {
					resourceSet.getResource(library, true);
				}
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
			diagnostics.addAll(validate(r)); // includes the structure rule (TriadCommonValidator)
		}
		Application application = assemble(resources);
		if (application.getName() == null) {
			application.setName(dir.getFileName() == null ? "application" : dir.getFileName().toString());
		}
		Collections.sort(diagnostics);
		return new LoadedApplication(dir, resourceSet, application, List.copyOf(diagnostics));
	}

	/**
	 * The application formed by {@code resources} (already loaded and linked): named after its class
	 * diagram, with its robot, world, goals, tasks and situations. Where the structure rule is broken
	 * the first element in a stable order is taken; the validators report the violation, so callers
	 * that generate or run check {@link #violations} (or the load's diagnostics) first.
	 */
	public static Application assemble(Iterable<? extends Resource> resources) {
		Application app = TriadFactory.eINSTANCE.createApplication();
		List<EObject> parts = new ArrayList<>();
		for (Resource r : inFileOrder(resources)) {
			for (EObject root : r.getContents()) {
				if (root instanceof ClassDiagram cd) {
					parts.add(cd);
				} else if (root instanceof ActorModel m && m.getActor() != null) {
					parts.add(m.getActor());
				} else if (root instanceof GoalModel m) {
					app.getGoals().addAll(m.getGoals());
				} else if (root instanceof TaskModel m) {
					app.getTasks().addAll(m.getTasks());
				} else if (root instanceof StateModel m) {
					app.getSituations().addAll(m.getSituations());
				}
			}
		}
		ApplicationStructure structure = ApplicationStructure.of(parts);
		app.setName(structure.applicationName());
		app.setDomain(structure.classDiagram());
		app.setRobot(structure.robot());
		app.setWorld(structure.world());
		return app;
	}

	/** The structure rule's violations among {@code resources}, as {@link #assemble} sees them. */
	public static List<ApplicationStructure.Violation> violations(Iterable<? extends Resource> resources) {
		List<EObject> parts = new ArrayList<>();
		for (Resource r : resources) {
			for (EObject root : r.getContents()) {
				if (root instanceof ClassDiagram cd) {
					parts.add(cd);
				} else if (root instanceof ActorModel m && m.getActor() != null) {
					parts.add(m.getActor());
				} else if (root instanceof org.triad.dsl.arc.ArcModel m && m.getComponent() != null) {
					parts.add(m.getComponent());
				}
			}
		}
		return ApplicationStructure.of(parts).violations();
	}

	/** A {@link FileIssueCodes#TOO_LARGE} error for each file over {@link #MAX_MODEL_FILE_BYTES}. */
	private static List<ModelDiagnostic> tooLarge(List<Path> files) {
		List<ModelDiagnostic> result = new ArrayList<>();
		for (Path file : files) {
			long size;
			try {
				size = Files.size(file);
			} catch (IOException e) {
				continue; // the load reports a file it cannot read
			}
			if (size > MAX_MODEL_FILE_BYTES) {
				result.add(new ModelDiagnostic(file, 1, 1, ModelDiagnostic.Severity.ERROR, FileIssueCodes.TOO_LARGE,
						"the file has " + size + " bytes; Triad reads model files of at most " + MAX_MODEL_FILE_BYTES + " bytes (2 MiB)"));
			}
		}
		return result;
	}

	private static List<String> relativePaths(Path dir, List<Path> files) {
		return files.stream().map(f -> dir.relativize(f).toString().replace('\\', '/')).toList();
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


	/** Resources sorted by their path, so every build (CLI, Maven, Gradle) lists goals and tasks in one order. */
	private static List<Resource> inFileOrder(Iterable<? extends Resource> resources) {
		List<Resource> sorted = new ArrayList<>();
		resources.forEach(sorted::add);
		sorted.sort(java.util.Comparator.comparing(r -> r.getURI().isFile() ? r.getURI().toFileString() : r.getURI().toString()));
		return sorted;
	}
}
