package org.triad.cli;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code triad new DIR --name Pharmacy}: a new application project from Triad's Maven archetype. */
@Command(name = "new", mixinStandardHelpOptions = true,
		description = { "Create a new application project in DIR (which must not exist or be empty), outside this repository:",
				"a small working example model, the generated code wired into its Maven build, a fake robot and world,",
				"a JUnit test that runs a task through RefArc, and a README. The same as",
				"'mvn archetype:generate -DarchetypeGroupId=org.triad -DarchetypeArtifactId=triad-archetype'.",
				"Exit code: 0 created, 2 bad input (a name that is not a Java identifier, a folder that is not empty)." })
public final class NewCommand implements Callable<Integer> {
	private static final Pattern APP_NAME = Pattern.compile("[A-Z][A-Za-z0-9]*");
	private static final Pattern JAVA_PACKAGE = Pattern.compile("[a-z_][a-z0-9_]*(\\.[a-z_][a-z0-9_]*)*");

	@Parameters(index = "0", paramLabel = "DIR", description = "the project's folder")
	private Path dir;

	@Option(names = "--name", required = true, paramLabel = "NAME",
			description = "the application's name, e.g. Pharmacy: its class diagram; generated package generated.<name in lower case>")
	private String name;

	@Option(names = "--group-id", paramLabel = "GROUP", description = "the project's Maven groupId (default: ${DEFAULT-VALUE})")
	private String groupId = "com.example";

	@Option(names = "--artifact-id", paramLabel = "ARTIFACT", description = "the project's Maven artifactId (default: the name in lower case)")
	private String artifactId;

	@Option(names = "--package", paramLabel = "PACKAGE", description = "the Java package of the robot and world (default: GROUP.<name in lower case>)")
	private String javaPackage;

	@CommandLine.Spec
	private CommandLine.Model.CommandSpec spec;

	@Override
	public Integer call() throws Exception {
		if (!APP_NAME.matcher(name).matches()) {
			throw new ModelSession.UserError("--name takes a name that starts with a capital letter followed by letters and digits, e.g. Pharmacy; not '"
					+ name + "'");
		}
		String lower = name.toLowerCase(java.util.Locale.ROOT);
		String pkg = javaPackage != null ? javaPackage : groupId + "." + lower;
		if (!JAVA_PACKAGE.matcher(pkg).matches() || !JAVA_PACKAGE.matcher(groupId).matches()) {
			throw new ModelSession.UserError("--package and --group-id take a Java package name such as com.example.pharmacy, not '"
					+ (JAVA_PACKAGE.matcher(groupId).matches() ? pkg : groupId) + "'");
		}
		if (Files.exists(dir) && (!Files.isDirectory(dir) || !isEmpty(dir))) {
			throw new ModelSession.UserError(dir + " exists and is not an empty folder; name a new one");
		}
		ArchetypeProject project = ArchetypeProject.fromClassPath(getClass().getClassLoader());
		int files = project.generate(dir, new ArchetypeProject.Properties(name, groupId, artifactId != null ? artifactId : lower, "0.1.0-SNAPSHOT",
				pkg, ArchetypeProject.TRIAD_VERSION));
		PrintWriter out = spec.commandLine().getOut();
		out.println("created application " + name + " in " + dir + " (" + files + " files)");
		out.println("  cd " + dir + " && mvn verify      # generates the Java from src/main/models, runs RestockTest through RefArc");
		if (!ArchetypeProject.triadArtifactsInstalled()) {
			out.println("Triad's artifacts are not in your local Maven repository yet; install them once from the Triad checkout:");
			out.println("  mvn -B install -DskipTests -pl refarc,generator,archetype -am");
		}
		return 0;
	}

	private static boolean isEmpty(Path dir) throws java.io.IOException {
		try (Stream<Path> entries = Files.list(dir)) {
			return entries.findAny().isEmpty();
		}
	}
}
