package org.triad.generator.java;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;

import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.dsl.app.ModelDiagnostic;
import org.triad.dsl.triad.Actor;
import org.triad.dsl.triad.Application;
import org.triad.dsl.triad.DomainClass;
import org.triad.dsl.triad.DomainType;
import org.triad.dsl.triad.Enumeration;
import org.triad.dsl.triad.Goal;
import org.triad.dsl.triad.Task;
import org.triad.generator.SchemaBuilder;

/**
 * Generates the Java code of an application (paper, Sect. 4): domain classes, {@code IRobot} and
 * {@code IWorld}, goal and task classes, the application schema, and the state provider and action
 * executor behaviours of RefArc. The models must have been checked without errors.
 * <p>
 * The one generator entry of every build: the command line ({@code triad generate}), the Maven build
 * (through {@link TriadApplicationGenerator}) and the Gradle plugin load an application with
 * {@link ApplicationAssembler#load} and write it with {@link #generate(Application, String, Path)}
 * (or take {@link #files} for an Xtext file system access).
 */
public final class TriadJavaGenerator {
	/** One generated compilation unit. */
	public record GeneratedFile(String qualifiedName, String content) {
		public GeneratedFile {
			// templates indent blank lines too; generated code carries no trailing blanks
			content = EXTRA_BLANK_LINES.matcher(TRAILING_BLANKS.matcher(content).replaceAll("")).replaceAll("\n\n");
		}

		/** The file's path relative to a source root. */
		public Path relativePath() {
			return Path.of(qualifiedName.replace('.', '/') + ".java");
		}
	}

	private static final Pattern TRAILING_BLANKS = Pattern.compile("[ \t]+$", Pattern.MULTILINE);
	private static final Pattern EXTRA_BLANK_LINES = Pattern.compile("\n{3,}");

	private TriadJavaGenerator() {
	}

	/** Every compilation unit of the application, in a stable order. */
	public static List<GeneratedFile> files(Application app, String basePackage) {
		requireComplete(app);
		TriadNames names = new TriadNames(app, basePackage);
		List<GeneratedFile> files = new ArrayList<>();
		DomainTypeTemplate domain = new DomainTypeTemplate(names);
		for (DomainType t : app.getDomain().getTypes()) {
			if (t instanceof DomainClass c) {
				files.add(new GeneratedFile(names.qualifiedDomainClass(c), domain.domainClass(c)));
			} else if (t instanceof Enumeration e) {
				files.add(new GeneratedFile(names.qualifiedDomainClass(e), domain.enumeration(e)));
			}
		}
		List<DomainClass> concreteClasses = concreteClasses(app);
		ActorInterfaceTemplate actors = new ActorInterfaceTemplate(names);
		files.add(new GeneratedFile(names.qualifiedRobotInterface(), actors.robotInterface(app.getRobot())));
		files.add(new GeneratedFile(names.qualifiedWorldInterface(), actors.worldInterface(app.getWorld(), concreteClasses)));
		GoalTemplate goals = new GoalTemplate(names);
		for (Goal g : app.getGoals()) {
			files.add(new GeneratedFile(names.qualifiedGoalClass(g), goals.goalClass(g)));
		}
		TaskTemplate tasks = new TaskTemplate(names);
		for (Task t : app.getTasks()) {
			files.add(new GeneratedFile(names.qualifiedTaskClass(t), tasks.taskClass(t)));
		}
		files.add(new GeneratedFile(names.qualifiedSchemaClass(), new SchemaTemplate(names).schemaClass(SchemaBuilder.build(app))));
		BehaviourTemplate behaviours = new BehaviourTemplate(names);
		List<Actor> bothActors = List.of(app.getRobot(), app.getWorld());
		files.add(new GeneratedFile(names.qualifiedStateProviderClass(), behaviours.stateProvider(bothActors, concreteClasses)));
		files.add(new GeneratedFile(names.qualifiedActionExecutorClass(), behaviours.actionExecutor(bothActors)));
		files.add(new GeneratedFile(names.qualifiedRefArcClass(), new RefArcTemplate(names).refArcClass()));
		return files;
	}

	/** Writes every compilation unit below {@code outDir}; returns the files written. */
	public static List<Path> generate(Application app, String basePackage, Path outDir) {
		List<Path> written = new ArrayList<>();
		for (GeneratedFile f : files(app, basePackage)) {
			Path target = outDir.resolve(f.relativePath());
			try {
				Files.createDirectories(target.getParent());
				Files.writeString(target, f.content(), StandardCharsets.UTF_8);
			} catch (IOException e) {
				throw new UncheckedIOException("cannot write " + target + ": " + e.getMessage(), e);
			}
			written.add(target);
		}
		return written;
	}

	/** The classes whose objects can exist: those that are not abstract. */
	static List<DomainClass> concreteClasses(Application app) {
		return app.getDomain().getTypes().stream()
				.filter(t -> t instanceof DomainClass c && !c.isAbstract())
				.map(DomainClass.class::cast)
				.toList();
	}

	private static void requireComplete(Application app) {
		if (app.getDomain() == null || app.getRobot() == null || app.getWorld() == null) {
			throw new IllegalArgumentException("application '" + app.getName()
					+ "' needs a class diagram, a robot and a world before Java can be generated");
		}
	}

	/**
	 * {@code TriadJavaGenerator <model folder> <output folder> [base package]}: checks the models, prints
	 * their diagnostics, and generates only if there are no errors (exit status 1 otherwise).
	 */
	public static void main(String[] args) {
		if (args.length < 2 || args.length > 3) {
			System.err.println("usage: TriadJavaGenerator <model folder> <output folder> [base package]");
			System.exit(2);
		}
		Path models = Path.of(args[0]);
		LoadedApplication loaded = ApplicationAssembler.load(models);
		for (ModelDiagnostic d : loaded.diagnostics()) {
			System.err.println(d.format(Path.of("").toAbsolutePath()));
		}
		if (loaded.hasErrors()) {
			System.exit(1);
		}
		Application app = loaded.application();
		String pkg = args.length == 3 ? args[2] : TriadNames.defaultBasePackage(app);
		List<Path> written = generate(app, pkg, Path.of(args[1]));
		System.out.println("generated " + written.size() + " Java files for application '" + app.getName() + "' in package " + pkg);
	}
}
