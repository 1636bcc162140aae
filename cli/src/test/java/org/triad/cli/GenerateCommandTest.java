package org.triad.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code triad generate} writes the application's Java, which compiles warning-free against the runtime. */
class GenerateCommandTest {

	@Test
	void generatedHospitalJavaCompilesWithoutWarnings(@TempDir Path tmp) throws Exception {
		StringWriter out = new StringWriter();
		StringWriter err = new StringWriter();
		int code = TriadCli.execute(new String[] { "generate", "../models/hospital/src/main/models", "-o", tmp.resolve("src").toString() },
				new PrintWriter(out, true), new PrintWriter(err, true));
		assertEquals(0, code, out + err.toString());
		assertTrue(out.toString().contains("of package generated.hospital"), out.toString());
		List<String> args = new ArrayList<>(List.of("-Xlint:all", "-Werror", "-d", tmp.resolve("classes").toString(), "-cp",
				System.getProperty("java.class.path")));
		try (Stream<Path> files = Files.walk(tmp.resolve("src"))) {
			files.filter(p -> p.toString().endsWith(".java")).forEach(p -> args.add(p.toString()));
		}
		assertTrue(Files.exists(tmp.resolve("src/generated/hospital/IRobot.java")));
		JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
		StringWriter diagnostics = new StringWriter();
		int result = javac.run(null, null, new java.io.ByteArrayOutputStream() {
			@Override
			public void flush() {
				diagnostics.write(toString());
			}
		}, args.toArray(String[]::new));
		assertEquals(0, result, diagnostics.toString());
	}

	@Test
	void theApplicationFolderGeneratesTheSameApplicationAsItsModelsFolder(@TempDir Path tmp) throws Exception {
		StringWriter out = new StringWriter();
		int code = TriadCli.execute(new String[] { "generate", "../models/hospital", "-o", tmp.toString() }, new PrintWriter(out, true),
				new PrintWriter(new StringWriter(), true));
		assertEquals(0, code, out.toString());
		assertTrue(out.toString().contains("of package generated.hospital"), out.toString());
		assertTrue(Files.exists(tmp.resolve("generated/hospital/HospitalActionExecutor.java")));
	}

	@Test
	void modelErrorsStopGenerationWithTheirLocation(@TempDir Path tmp) throws Exception {
		Files.writeString(tmp.resolve("Bad.cd"), "classdiagram Bad { class A extends Missing; }");
		StringWriter out = new StringWriter();
		int code = TriadCli.execute(new String[] { "generate", tmp.toString(), "-o", tmp.resolve("out").toString() },
				new PrintWriter(out, true), new PrintWriter(new StringWriter(), true));
		assertEquals(1, code);
		assertTrue(out.toString().startsWith("Bad.cd:1:"), out.toString());
		assertTrue(Files.notExists(tmp.resolve("out")));
	}
}
