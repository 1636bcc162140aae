import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.Enumeration;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.Set;
import java.util.TreeSet;
import java.util.jar.Attributes;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;
import java.util.stream.Stream;

import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;

import org.gradle.internal.impldep.org.objectweb.asm.ClassReader;
import org.gradle.internal.impldep.org.objectweb.asm.ClassWriter;
import org.gradle.internal.impldep.org.objectweb.asm.commons.ClassRemapper;
import org.gradle.internal.impldep.org.objectweb.asm.commons.Remapper;

/**
 * Lays out a Gradle 8.10 installation from Maven Central artifacts alone:
 * {@code java -cp ARTIFACTS_DIR/gradle-api-8.10.jar AssembleGradle.java ARTIFACTS_DIR SHIMS_DIR OUTPUT_DIR}
 * (the class path lends it the jar's relocated ASM).
 *
 * <p>{@code dev.gradleplugins:gradle-api:8.10} holds Gradle's classes (its third-party libraries
 * relocated) and the module manifests {@code gradle-*-classpath.properties} that Gradle's module
 * registry reads from {@code lib/gradle-*-8.10.jar}. A distribution's {@code lib/} is made of:
 * <ul>
 * <li>{@code gradle-classes-8.10.jar}: that jar once, without its SFTP file-system provider (on the
 * launcher's class path it makes the JDK's provider lookup circular);
 * <li>one small jar per module holding only its module manifest, whose jar manifest's
 * {@code Class-Path} names {@code gradle-classes} (module implementation class paths, e.g. a worker
 * process's, are module jars alone);
 * <li>the unrelocated libraries (Groovy, Kotlin's standard library, the JUnit Platform launcher that
 * test workers run) from ARTIFACTS_DIR, and an empty placeholder for every relocated one, so the module
 * registry finds each name it looks for;
 * <li>in {@code gradle-classes}, the classes of Gradle's JUnit Platform test framework (the test
 * worker's launcher session and listener, and the framework's shared packages and distribution modules)
 * with their references to the relocated JUnit Platform turned back into the real one, as in a
 * distribution of Gradle: the relocated launcher finds no test engine, since the project's engines
 * implement the real {@code org.junit.platform.engine.TestEngine};
 * <li>the modules the jar lacks, built from {@code shims/}: {@code gradle-gradle-cli} (the
 * command-line entry, running the build in the launching JVM), {@code gradle-java-compiler-plugin}
 * (javac without Gradle's incremental-compilation bookkeeping, so every compileJava run is whole) and
 * {@code gradle-installation-beacon} (what {@code gradleApi()} looks for).
 * </ul>
 * No Kotlin DSL: gradle-api holds none of it (a .kts script stops at {@code ClassNotFoundException:
 * org.gradle.kotlin.dsl.provider.KotlinScriptPluginFactory}) and Gradle publishes {@code gradle-kotlin-dsl}
 * to no registry these machines reach, so builds are Groovy scripts.
 */
public final class AssembleGradle {
	private static final String VERSION = "8.10";
	private static final String CLASSES = "gradle-classes-" + VERSION + ".jar";
	private static final String SFTP_PROVIDER = "META-INF/services/java.nio.file.spi.FileSystemProvider";
	private static final String JAR_INDEX = "META-INF/INDEX.LIST";
	private static final String JUNIT_PLATFORM_FRAMEWORK = "org/gradle/api/internal/tasks/testing/junitplatform/";
	private static final String IMPLDEP = "org/gradle/internal/impldep/";
	private static final List<String> UNRELOCATED = List.of("org/junit/", "org/opentest4j/");
	/** Part of the up-to-date stamp: changes whenever this program lays out lib/ differently. */
	private static final String LAYOUT = "layout 2: the JUnit Platform test framework unrelocated";

	public static void main(String[] args) throws IOException {
		if (args.length != 3) {
			System.err.println("usage: java AssembleGradle.java ARTIFACTS_DIR SHIMS_DIR OUTPUT_DIR");
			System.exit(2);
		}
		Path artifacts = Path.of(args[0]).toAbsolutePath();
		Path shims = Path.of(args[1]).toAbsolutePath();
		Path out = Path.of(args[2]).toAbsolutePath();
		Path api = artifacts.resolve("gradle-api-" + VERSION + ".jar");
		if (!Files.isRegularFile(api)) {
			System.err.println("assemble-gradle: " + api + " is missing (mvn dependency:copy@gradle-artifacts fetches it)");
			System.exit(2);
		}
		String stamp = LAYOUT + "\n" + stamp(artifacts, shims);
		Path stampFile = out.resolve(".assembled");
		if (Files.isRegularFile(stampFile) && Files.readString(stampFile).equals(stamp) && Files.isExecutable(out.resolve("bin/gradle"))) {
			System.out.println("Gradle " + VERSION + " in " + out + " is up to date");
			return;
		}
		deleteTree(out);
		Path lib = Files.createDirectories(out.resolve("lib"));
		Files.createDirectories(lib.resolve("plugins")); // Gradle recognises its installation by lib/plugins
		copyWithout(api, lib.resolve(CLASSES), Set.of(SFTP_PROVIDER, JAR_INDEX), junitPlatformFrameworkUnrelocated(api));

		Map<String, Properties> manifests = manifests(api);
		TreeSet<String> runtimeLibraries = new TreeSet<>();
		TreeSet<String> referencedModules = new TreeSet<>();
		for (Properties p : manifests.values()) {
			runtimeLibraries.addAll(list(p.getProperty("runtime", "")));
			referencedModules.addAll(list(p.getProperty("projects", "")));
		}
		for (Map.Entry<String, Properties> m : manifests.entrySet()) {
			moduleJar(lib, m.getKey(), m.getValue().getProperty("projects", ""), withClasses(m.getValue().getProperty("runtime", "")), Map.of());
		}
		Path shimClasses = compileShims(shims, out.resolve("shim-classes"), lib.resolve(CLASSES), artifacts);
		moduleJar(lib, "gradle-gradle-cli", "gradle-launcher", CLASSES, classesBelow(shimClasses, "org/gradle/launcher"));
		moduleJar(lib, "gradle-java-compiler-plugin", "", "", classesBelow(shimClasses, "org/gradle/internal/compiler"));
		moduleJar(lib, "gradle-installation-beacon", "", "", classesBelow(shimClasses, "org/gradle/internal/installation"));
		referencedModules.removeAll(manifests.keySet());
		referencedModules.remove("gradle-java-compiler-plugin");
		for (String missing : referencedModules) {
			moduleJar(lib, missing, "", CLASSES, Map.of()); // named by other modules, its classes are in gradle-classes
		}
		for (String library : runtimeLibraries) {
			Path real = artifacts.resolve(library);
			if (Files.isRegularFile(real)) {
				Files.copy(real, lib.resolve(library));
			} else {
				moduleJar(lib, null, null, null, Map.of(), lib.resolve(library)); // relocated into gradle-classes
			}
		}
		deleteTree(shimClasses);
		Path bin = Files.createDirectories(out.resolve("bin"));
		Path gradle = bin.resolve("gradle");
		Files.writeString(gradle, String.join("\n",
				"#!/bin/sh",
				"# Gradle " + VERSION + " assembled from Maven Central artifacts (gradle-plugin/assemble-gradle.sh); runs builds in this JVM",
				"APP_HOME=$(cd \"$(dirname \"$0\")/..\" && pwd -P)",
				"exec java ${JAVA_OPTS:-} ${GRADLE_OPTS:--Xmx1g} -cp \"$APP_HOME/lib/gradle-gradle-cli-main-" + VERSION + ".jar:$APP_HOME/lib/" + CLASSES
						+ "\" org.gradle.launcher.GradleMain \"$@\"",
				""));
		gradle.toFile().setExecutable(true);
		Files.writeString(stampFile, stamp);
		System.out.println("assembled Gradle " + VERSION + " in " + out + " (" + manifests.size() + " modules, " + runtimeLibraries.size() + " libraries)");
	}

	/** What the installation is made of: names, sizes and times of the artifacts and shim sources. */
	private static String stamp(Path... folders) throws IOException {
		StringBuilder b = new StringBuilder();
		for (Path folder : folders) {
			try (Stream<Path> walk = Files.walk(folder)) {
				for (Path p : walk.filter(Files::isRegularFile).sorted().toList()) {
					b.append(p).append(' ').append(Files.size(p)).append(' ').append(Files.getLastModifiedTime(p).toMillis()).append('\n');
				}
			}
		}
		return b.toString();
	}

	private static List<String> list(String csv) {
		List<String> l = new ArrayList<>();
		for (String s : csv.split(",")) {
			if (!s.isBlank()) {
				l.add(s.trim());
			}
		}
		return l;
	}

	private static String withClasses(String runtime) {
		return runtime.isBlank() ? CLASSES : runtime + "," + CLASSES;
	}

	private static Map<String, Properties> manifests(Path api) throws IOException {
		Map<String, Properties> result = new LinkedHashMap<>();
		try (JarFile jar = new JarFile(api.toFile())) {
			for (Enumeration<JarEntry> e = jar.entries(); e.hasMoreElements();) {
				JarEntry entry = e.nextElement();
				String name = entry.getName();
				if (!name.contains("/") && name.endsWith("-classpath.properties")) {
					Properties p = new Properties();
					try (InputStream in = jar.getInputStream(entry)) {
						p.load(in);
					}
					result.put(name.substring(0, name.length() - "-classpath.properties".length()), p);
				}
			}
		}
		return result;
	}

	private static void moduleJar(Path lib, String module, String projects, String runtime, Map<String, byte[]> classes) throws IOException {
		moduleJar(lib, module, projects, runtime, classes, lib.resolve(module + "-" + VERSION + ".jar"));
	}

	private static void moduleJar(Path lib, String module, String projects, String runtime, Map<String, byte[]> classes, Path target)
			throws IOException {
		Manifest manifest = new Manifest();
		manifest.getMainAttributes().put(Attributes.Name.MANIFEST_VERSION, "1.0");
		if (module != null) {
			// every class loader and worker class path that has a module jar gets Gradle's classes through it
			manifest.getMainAttributes().put(Attributes.Name.CLASS_PATH, CLASSES);
		}
		try (JarOutputStream jar = new JarOutputStream(Files.newOutputStream(target), manifest)) {
			if (module != null) {
				jar.putNextEntry(new JarEntry(module + "-classpath.properties"));
				jar.write(("projects=" + projects + "\nruntime=" + runtime + "\n").getBytes(StandardCharsets.ISO_8859_1));
				jar.closeEntry();
			}
			for (Map.Entry<String, byte[]> c : classes.entrySet()) {
				jar.putNextEntry(new JarEntry(c.getKey()));
				jar.write(c.getValue());
				jar.closeEntry();
			}
		}
	}

	private static void copyWithout(Path from, Path to, Set<String> skipped, Map<String, byte[]> replaced) throws IOException {
		try (JarFile in = new JarFile(from.toFile()); JarOutputStream out = new JarOutputStream(Files.newOutputStream(to))) {
			byte[] buffer = new byte[1 << 16];
			for (Enumeration<JarEntry> e = in.entries(); e.hasMoreElements();) {
				JarEntry entry = e.nextElement();
				if (skipped.contains(entry.getName())) {
					continue;
				}
				out.putNextEntry(new JarEntry(entry.getName()));
				if (replaced.containsKey(entry.getName())) {
					out.write(replaced.get(entry.getName()));
					out.closeEntry();
					continue;
				}
				try (InputStream s = in.getInputStream(entry)) {
					for (int n; (n = s.read(buffer)) > 0;) {
						out.write(buffer, 0, n);
					}
				}
				out.closeEntry();
			}
		}
	}

	/**
	 * The classes of Gradle's JUnit Platform test framework that name the relocated JUnit Platform (as
	 * types, or as class and package names in strings), rewritten to name the real one, which the
	 * project's test runtime class path (or lib/) provides as in a distribution of Gradle.
	 */
	private static Map<String, byte[]> junitPlatformFrameworkUnrelocated(Path api) throws IOException {
		Remapper unrelocate = new Remapper() {
			@Override
			public String map(String internalName) {
				return unrelocated(internalName, IMPLDEP);
			}

			@Override
			public Object mapValue(Object value) {
				return value instanceof String s ? unrelocated(unrelocated(s, IMPLDEP), IMPLDEP.replace('/', '.')) : super.mapValue(value);
			}
		};
		Map<String, byte[]> result = new LinkedHashMap<>();
		try (JarFile jar = new JarFile(api.toFile())) {
			for (Enumeration<JarEntry> e = jar.entries(); e.hasMoreElements();) {
				JarEntry entry = e.nextElement();
				if (!entry.getName().startsWith(JUNIT_PLATFORM_FRAMEWORK) || !entry.getName().endsWith(".class")) {
					continue;
				}
				byte[] original;
				try (InputStream in = jar.getInputStream(entry)) {
					original = in.readAllBytes();
				}
				String constants = new String(original, StandardCharsets.ISO_8859_1);
				if (UNRELOCATED.stream().anyMatch(prefix -> constants.contains(IMPLDEP + prefix)
						|| constants.contains((IMPLDEP + prefix).replace('/', '.').replaceAll("\\.$", "")))) {
					ClassWriter writer = new ClassWriter(0);
					new ClassReader(original).accept(new ClassRemapper(writer, unrelocate), 0);
					result.put(entry.getName(), writer.toByteArray());
				}
			}
		}
		if (result.isEmpty()) {
			throw new IllegalStateException("no class of " + JUNIT_PLATFORM_FRAMEWORK + " in " + api + " uses the relocated JUnit Platform");
		}
		return result;
	}

	/** {@code name} without the relocation prefix when it names a relocated JUnit Platform or opentest4j class or package. */
	private static String unrelocated(String name, String relocation) {
		for (String prefix : UNRELOCATED) {
			String p = relocation.endsWith(".") ? prefix.replace('/', '.') : prefix;
			String relocated = relocation + p;
			if (name.startsWith(relocated) || name.equals(relocated.substring(0, relocated.length() - 1))) {
				return name.substring(relocation.length());
			}
		}
		return name;
	}

	private static Path compileShims(Path sources, Path classesDir, Path gradleClasses, Path artifacts) throws IOException {
		List<String> files;
		try (Stream<Path> walk = Files.walk(sources)) {
			files = walk.filter(p -> p.toString().endsWith(".java")).map(Path::toString).toList();
		}
		Files.createDirectories(classesDir);
		JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
		List<String> args = new ArrayList<>(List.of("-nowarn", "-d", classesDir.toString(), "-cp",
				gradleClasses + java.io.File.pathSeparator + artifacts.resolve("groovy-3.0.22.jar")));
		args.addAll(files);
		OutputStream quiet = OutputStream.nullOutputStream();
		if (javac.run(null, quiet, System.err, args.toArray(String[]::new)) != 0) {
			throw new IllegalStateException("the shims in " + sources + " do not compile against Gradle " + VERSION);
		}
		return classesDir;
	}

	private static Map<String, byte[]> classesBelow(Path root, String folder) throws IOException {
		Map<String, byte[]> classes = new LinkedHashMap<>();
		try (Stream<Path> walk = Files.walk(root.resolve(folder))) {
			for (Path p : walk.filter(Files::isRegularFile).toList()) {
				classes.put(root.relativize(p).toString().replace(java.io.File.separatorChar, '/'), Files.readAllBytes(p));
			}
		}
		return classes;
	}

	private static void deleteTree(Path dir) {
		if (!Files.exists(dir)) {
			return;
		}
		try (Stream<Path> walk = Files.walk(dir)) {
			for (Path p : walk.sorted(Comparator.reverseOrder()).toList()) {
				Files.delete(p);
			}
		} catch (IOException e) {
			throw new UncheckedIOException(e);
		}
	}
}
