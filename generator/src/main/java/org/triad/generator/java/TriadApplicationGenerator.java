package org.triad.generator.java;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.generator.AbstractGenerator;
import org.eclipse.xtext.generator.IFileSystemAccess2;
import org.eclipse.xtext.generator.IGeneratorContext;
import org.triad.dsl.triad.Actor;
import org.triad.dsl.triad.ActorKind;
import org.triad.dsl.triad.ActorModel;
import org.triad.dsl.triad.Application;
import org.triad.dsl.triad.ClassDiagram;
import org.triad.dsl.triad.GoalModel;
import org.triad.dsl.triad.StateModel;
import org.triad.dsl.triad.TaskModel;
import org.triad.dsl.triad.TriadFactory;

/**
 * The Java generator as an Xtext {@code IGenerator2}, for the {@code xtext-maven-plugin} and other
 * Xtext builders. Bound to the class-diagram language (see {@link TriadJavaGeneratorSetup}): the class
 * diagram's resource generates the whole application, assembled from every model in its resource
 * set, because IRobot, IWorld, the schema and the behaviours depend on all of them.
 */
public class TriadApplicationGenerator extends AbstractGenerator {
	@Override
	public void doGenerate(Resource input, IFileSystemAccess2 fsa, IGeneratorContext context) {
		if (input.getContents().isEmpty() || !(input.getContents().get(0) instanceof ClassDiagram)) {
			return;
		}
		Application app = assemble(input);
		for (TriadJavaGenerator.GeneratedFile f : TriadJavaGenerator.files(app, TriadNames.defaultBasePackage(app))) {
			fsa.generateFile(f.relativePath().toString().replace('\\', '/'), f.content());
		}
	}

	/** The application whose class diagram is {@code input}: every model in the same resource set. */
	static Application assemble(Resource input) {
		EcoreUtil.resolveAll(input.getResourceSet());
		Application app = TriadFactory.eINSTANCE.createApplication();
		app.setName(applicationName(input.getURI()));
		app.setDomain((ClassDiagram) input.getContents().get(0));
		List<Actor> robots = new ArrayList<>();
		List<Actor> worlds = new ArrayList<>();
		// in file order, as ApplicationLoader loads them, so Maven's output equals ./triad generate's and Gradle's
		List<Resource> resources = new ArrayList<>(input.getResourceSet().getResources());
		resources.sort(Comparator.comparing(TriadApplicationGenerator::fileOrder));
		for (Resource r : resources) {
			for (EObject root : r.getContents()) {
				if (root instanceof ActorModel m && m.getActor() != null) {
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
		app.setRobot(theOne(robots, "robot", app));
		app.setWorld(theOne(worlds, "world", app));
		return app;
	}

	private static String fileOrder(Resource r) {
		return r.getURI().isFile() ? r.getURI().toFileString() : r.getURI().toString();
	}

	private static Actor theOne(List<Actor> actors, String kind, Application app) {
		if (actors.size() != 1) {
			throw new IllegalStateException("application '" + app.getName() + "' needs exactly one " + kind + " to generate Java, found "
					+ (actors.isEmpty() ? "none" : actors.stream().map(a -> a.getName() + " (" + a.eResource().getURI().lastSegment() + ")")
							.collect(Collectors.joining(", "))));
		}
		return actors.get(0);
	}

	private static String applicationName(URI cd) {
		if (cd.isFile()) {
			Path dir = Path.of(cd.toFileString()).getParent();
			if (dir != null) {
				return TriadJavaGenerator.applicationName(dir);
			}
		}
		return cd.trimFileExtension().lastSegment();
	}
}
