package org.triad.dsl.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.dsl.validation.FileIssueCodes;

/**
 * A model file over {@link ApplicationAssembler#MAX_MODEL_FILE_BYTES} is refused with one located
 * line, {@code path:1:1: error file.too-large: ...}, and nothing else is read; a file at the limit is
 * read (the rule's good case is every other model test: none of them is refused).
 */
class ModelFileSizeTest {
	@TempDir
	Path app;

	@Test
	void aFileOverTheLimitIsRefusedWithOneLocatedLine() throws IOException {
		copyBase();
		Path big = app.resolve("Big.goal");
		try (OutputStream out = Files.newOutputStream(big)) {
			out.write("domain Shop;\n//".getBytes());
			out.write(new byte[(int) ApplicationAssembler.MAX_MODEL_FILE_BYTES]); // no need to be a model: it is not read
		}
		LoadedApplication loaded = ApplicationAssembler.load(app);
		List<String> lines = loaded.diagnostics().stream().map(d -> d.format(loaded.root())).toList();
		assertEquals(1, lines.size(), lines::toString);
		assertTrue(lines.get(0).startsWith("Big.goal:1:1: error " + FileIssueCodes.TOO_LARGE + ": the file has " + Files.size(big)
				+ " bytes; Triad reads model files of at most " + ApplicationAssembler.MAX_MODEL_FILE_BYTES + " bytes"), lines.get(0));
		assertTrue(loaded.hasErrors());
	}

	@Test
	void aFileAtTheLimitIsRead() throws IOException {
		copyBase();
		Path padded = app.resolve("At.goal");
		String head = Files.readString(padded) + "\n";
		// the base's goal padded with a comment to exactly the limit: read and checked, without findings
		StringBuilder text = new StringBuilder(head).append("/*");
		text.append(" ".repeat((int) ApplicationAssembler.MAX_MODEL_FILE_BYTES - head.length() - 4)).append("*/");
		Files.writeString(padded, text);
		assertEquals(ApplicationAssembler.MAX_MODEL_FILE_BYTES, Files.size(padded));
		LoadedApplication loaded = ApplicationAssembler.load(app);
		assertEquals(List.of(), loaded.diagnostics().stream().filter(d -> d.code().equals(FileIssueCodes.TOO_LARGE)).toList());
		assertEquals(List.of(), loaded.diagnostics().stream().filter(ModelDiagnostic::isError).toList());
	}

	private void copyBase() throws IOException {
		try (Stream<Path> files = Files.list(Path.of("src", "test", "resources", "rules", "_base"))) {
			for (Path f : files.toList()) {
				Files.copy(f, app.resolve(f.getFileName()));
			}
		}
	}
}
