package org.triad.dsl.rules;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.triad.dsl.app.ModelDiagnostic;

/**
 * One folder below {@code src/test/resources/rules/<code>/}: a tiny application made of the base
 * application ({@code rules/_base}) with the case's files laid over it (same name replaces, new
 * names add; a file {@code omit} lists base files to leave out). Expected diagnostics are written
 * in the models, on the offending line, as {@code // expect: error CODE @COL} (column optional,
 * several separated by {@code ;}).
 */
record RuleCase(String code, String name, Path folder) {
	static final Path RULES = Path.of("src", "test", "resources", "rules");
	static final Path BASE = RULES.resolve("_base");

	private static final Pattern EXPECT = Pattern.compile("//\\s*expect:\\s*(.*)$");
	private static final Pattern CLAUSE = Pattern.compile("\\s*(error|warning)\\s+(\\S+)(?:\\s+@(\\d+))?\\s*");

	/** One expected diagnostic; {@code column} 0 means any column. */
	record Expectation(String file, int line, int column, String severity, String code) {
		boolean matches(ModelDiagnostic d, Path root) {
			return root.relativize(d.file()).toString().equals(file) && d.line() == line
					&& (column == 0 || d.column() == column) && d.severity().label().equals(severity) && d.code().equals(code);
		}

		@Override
		public String toString() {
			return file + ":" + line + ":" + (column == 0 ? "*" : column) + ": " + severity + " " + code;
		}
	}

	boolean isBad() {
		return name.startsWith("bad");
	}

	/** Every case folder below rules/, sorted by code and name. */
	static List<RuleCase> all() {
		List<RuleCase> cases = new ArrayList<>();
		try (Stream<Path> codes = Files.list(RULES)) {
			for (Path codeDir : codes.filter(Files::isDirectory).filter(p -> !p.equals(BASE)).sorted().toList()) {
				try (Stream<Path> variants = Files.list(codeDir)) {
					for (Path v : variants.filter(Files::isDirectory).sorted().toList()) {
						cases.add(new RuleCase(codeDir.getFileName().toString(), v.getFileName().toString(), v));
					}
				}
			}
		} catch (IOException e) {
			throw new UncheckedIOException(e);
		}
		return cases;
	}

	/** Writes the case's application into {@code target}. */
	void materialize(Path target) throws IOException {
		Path omit = folder.resolve("omit");
		Set<String> omitted = Files.exists(omit) ? Set.copyOf(Files.readAllLines(omit).stream().map(String::trim)
				.filter(s -> !s.isEmpty()).toList()) : Set.of();
		for (Path from : List.of(BASE, folder)) {
			try (Stream<Path> files = Files.list(from)) {
				for (Path f : files.filter(Files::isRegularFile).toList()) {
					String n = f.getFileName().toString();
					if (!n.equals("omit") && !(from == BASE && omitted.contains(n))) {
						Files.copy(f, target.resolve(n), StandardCopyOption.REPLACE_EXISTING);
					}
				}
			}
		}
	}

	/** The expectations written in the case's own files (the base has none). */
	List<Expectation> expectations() throws IOException {
		List<Expectation> result = new ArrayList<>();
		try (Stream<Path> files = Files.list(folder)) {
			for (Path f : files.filter(Files::isRegularFile).sorted(Comparator.naturalOrder()).toList()) {
				List<String> lines = Files.readAllLines(f);
				for (int i = 0; i < lines.size(); i++) {
					Matcher m = EXPECT.matcher(lines.get(i));
					if (!m.find()) {
						continue;
					}
					for (String clause : m.group(1).split(";")) {
						Matcher c = CLAUSE.matcher(clause);
						if (!c.matches()) {
							throw new IllegalArgumentException(f + ":" + (i + 1) + ": cannot read expectation '" + clause + "'");
						}
						result.add(new Expectation(f.getFileName().toString(), i + 1, c.group(3) == null ? 0 : Integer.parseInt(c.group(3)),
								c.group(1), c.group(2)));
					}
				}
			}
		}
		return result;
	}

	@Override
	public String toString() {
		return code + "/" + name;
	}
}
