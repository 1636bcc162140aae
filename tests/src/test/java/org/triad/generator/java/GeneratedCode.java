package org.triad.generator.java;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.io.File;
import java.io.IOException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;

import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.dsl.triad.Application;

/** An application's models, the Java generated from them, compiled and loaded. */
final class GeneratedCode {
	final LoadedApplication loaded;
	final String basePackage;
	final List<Path> sources;
	final List<String> compilerMessages;
	final ClassLoader loader;

	private GeneratedCode(LoadedApplication loaded, String basePackage, List<Path> sources, List<String> compilerMessages, ClassLoader loader) {
		this.loaded = loaded;
		this.basePackage = basePackage;
		this.sources = sources;
		this.compilerMessages = compilerMessages;
		this.loader = loader;
	}

	/** Loads the models below {@code models}, generates Java into {@code dir} and compiles it with all warnings as errors. */
	static GeneratedCode of(Path models, Path dir) throws IOException {
		LoadedApplication loaded = ApplicationAssembler.load(models);
		assertFalse(loaded.hasErrors(), () -> "the example models have errors: " + loaded.diagnostics());
		Application app = loaded.application();
		String pkg = TriadNames.defaultBasePackage(app);
		Path src = Files.createDirectories(dir.resolve("src"));
		Path classes = Files.createDirectories(dir.resolve("classes"));
		List<Path> sources = TriadJavaGenerator.generate(app, pkg, src);
		JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
		DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
		try (StandardJavaFileManager fm = javac.getStandardFileManager(diagnostics, Locale.ROOT, null)) {
			List<String> options = List.of("-Xlint:all", "-Werror", "--release", "17", "-d", classes.toString(),
					"-classpath", System.getProperty("java.class.path"));
			javac.getTask(null, fm, diagnostics, options, null, fm.getJavaFileObjectsFromPaths(sources)).call();
		}
		List<String> messages = diagnostics.getDiagnostics().stream().map(GeneratedCode::format).toList();
		ClassLoader loader = new URLClassLoader(new URL[] { classes.toUri().toURL() }, GeneratedCode.class.getClassLoader());
		return new GeneratedCode(loaded, pkg, sources, messages, loader);
	}

	private static String format(Diagnostic<? extends JavaFileObject> d) {
		String file = d.getSource() == null ? "" : new File(d.getSource().toUri()).getName() + ":" + d.getLineNumber() + ": ";
		return file + d.getKind() + ": " + d.getMessage(Locale.ROOT);
	}

	void assertCompiledCleanly() {
		assertEquals(List.of(), compilerMessages, () -> "javac -Xlint:all -Werror on the generated code:\n"
				+ compilerMessages.stream().collect(Collectors.joining("\n")));
	}

	Class<?> load(String relativeName) throws ClassNotFoundException {
		return Class.forName(basePackage + "." + relativeName, true, loader);
	}

	String source(String relativeName) throws IOException {
		String rel = (basePackage + "." + relativeName).replace('.', '/') + ".java";
		return Files.readString(sources.stream().filter(p -> p.toString().replace(File.separatorChar, '/').endsWith(rel)).findFirst().orElseThrow());
	}
}
