package org.triad.generator.arc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.stream.Collectors;

import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.dsl.validation.ArcIssueCodes;

/**
 * The generator's output compiles with hand-written behavior classes and runs on the component
 * runtime: boxing of primitive port types, generic port types, a port named by a Java keyword, a
 * subcomponent from another package, configuration parameters passed down.
 */
class ArcGeneratorTest {
	private static final Map<String, String> MODELS = new LinkedHashMap<>();
	static {
		MODELS.put("demo/Scaler.arc", """
				package demo;
				/* Multiplies by its factor. */
				component Scaler(int factor) {
				  port in int in;
				  port out Integer out;
				}
				""");
		MODELS.put("demo/Batcher.arc", """
				package demo;
				component Batcher {
				  port in Integer new;
				  port out java.util.List<Integer> batch;
				}
				""");
		MODELS.put("app/Pipeline.arc", """
				package app;
				import demo.*;
				component Pipeline(int factor) {
				  port in Integer in;
				  port out Integer result;
				  port out java.util.List<Integer> batches;
				  Scaler first(factor);
				  demo.Scaler second(2);
				  Batcher batcher;
				  in -> first.in;
				  first.out -> second.in;
				  second.out -> result, batcher.new;
				  batcher.batch -> batches;
				}
				""");
	}
	private static final Map<String, String> HAND_WRITTEN = Map.of(
			"demo/Scaler.java", """
					package demo;
					public class Scaler extends ScalerTOP {
					    private final int factor;
					    public Scaler(int factor) { this.factor = factor; }
					    @Override protected void onIn(Integer message) { out.send(message * factor); }
					}
					""",
			"demo/Batcher.java", """
					package demo;
					public class Batcher extends BatcherTOP {
					    private final java.util.List<Integer> items = new java.util.ArrayList<>();
					    @Override protected void onNew(Integer message) {
					        items.add(message);
					        if (items.size() == 2) { batch.send(java.util.List.copyOf(items)); items.clear(); }
					    }
					}
					""",
			"app/Harness.java", """
					package app;
					import java.util.ArrayList;
					import java.util.List;
					import org.triad.runtime.component.DeterministicScheduler;
					import org.triad.runtime.component.Scheduler;
					public class Harness {
					    public static List<Object> run() {
					        Pipeline p = new Pipeline(3);
					        List<Object> seen = new ArrayList<>();
					        p.result.observe(seen::add);
					        p.batches.observe(seen::add);
					        DeterministicScheduler s = Scheduler.deterministic();
					        s.deploy(p);
					        s.send(p.in, 1);
					        s.send(p.in, 2);
					        s.runUntilIdle();
					        seen.addAll(s.unhandledFaults());
					        return seen;
					    }
					}
					""");

	@TempDir
	Path work;

	@Test
	void generatedJavaCompilesAndRuns() throws Exception {
		Path models = work.resolve("models");
		write(models, MODELS);
		Path src = work.resolve("src");
		List<Path> generated = ArcJavaGenerator.generate(models, src, HandwrittenCode.NONE, List.of());
		assertEquals(List.of("app/Pipeline.java", "demo/BatcherTOP.java", "demo/ScalerTOP.java"),
				generated.stream().map(p -> src.relativize(p).toString().replace(File.separatorChar, '/')).sorted().toList());
		assertTrue(Files.readString(src.resolve("demo/ScalerTOP.java")).contains("<p>Multiplies by its factor."), "model comment as javadoc");
		write(src, HAND_WRITTEN);
		Path classes = Files.createDirectories(work.resolve("classes"));
		compile(src, classes);
		try (URLClassLoader loader = new URLClassLoader(new URL[] { classes.toUri().toURL() }, getClass().getClassLoader())) {
			Object seen = loader.loadClass("app.Harness").getMethod("run").invoke(null);
			assertEquals(List.of(6, 12, List.of(6, 12)), seen);
		}
	}

	@Test
	void modelErrorsStopGenerationWithTheirLocation() throws Exception {
		Path models = work.resolve("bad");
		write(models, Map.of("Broken.arc", "package demo;\ncomponent Broken {\n  Missing part;\n}\n"));
		Path out = Files.createDirectories(work.resolve("out"));
		Files.writeString(out.resolve("Stale.java"), "class Stale {}");
		IllegalStateException e = assertThrows(IllegalStateException.class, () -> ArcJavaGenerator.generate(models, out, HandwrittenCode.NONE, List.of()));
		assertTrue(e.getMessage().contains("Broken.arc:3:3: error " + ArcIssueCodes.UNKNOWN_COMPONENT + ": unknown component type 'Missing'"),
				e.getMessage());
	}

	@Test
	void generationReplacesEarlierOutput() throws Exception {
		Path models = work.resolve("models");
		write(models, Map.of("demo/Batcher.arc", MODELS.get("demo/Batcher.arc")));
		Path out = Files.createDirectories(work.resolve("out/old"));
		Files.writeString(out.resolve("Stale.java"), "class Stale {}");
		ArcJavaGenerator.generate(models, work.resolve("out"), HandwrittenCode.NONE, List.of());
		assertTrue(Files.exists(work.resolve("out/demo/BatcherTOP.java")));
		assertTrue(Files.notExists(out.resolve("Stale.java")));
	}

	static void write(Path root, Map<String, String> files) throws Exception {
		for (Map.Entry<String, String> f : files.entrySet()) {
			Path p = root.resolve(f.getKey());
			Files.createDirectories(p.getParent());
			Files.writeString(p, f.getValue());
		}
	}

	static void compile(Path src, Path classes) throws Exception {
		List<File> sources = new ArrayList<>();
		try (var walk = Files.walk(src)) {
			walk.filter(p -> p.toString().endsWith(".java")).forEach(p -> sources.add(p.toFile()));
		}
		JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
		DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
		try (StandardJavaFileManager files = javac.getStandardFileManager(diagnostics, Locale.ROOT, null)) {
			List<String> options = List.of("-d", classes.toString(), "-classpath", System.getProperty("java.class.path"), "--release", "17",
					"-proc:none", "-Xlint:all,-path,-classfile,-options", "-Werror");
			boolean ok = javac.getTask(null, files, diagnostics, options, null, files.getJavaFileObjectsFromFiles(sources)).call();
			String problems = diagnostics.getDiagnostics().stream().filter(d -> d.getKind() != Diagnostic.Kind.NOTE)
					.map(d -> d.getSource() + ":" + d.getLineNumber() + ": " + d.getMessage(Locale.ROOT)).collect(Collectors.joining("\n"));
			assertEquals("", problems);
			assertTrue(ok);
		}
	}
}
