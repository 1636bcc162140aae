package org.triad.dsl;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Random;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.apache.log4j.AppenderSkeleton;
import org.apache.log4j.Level;
import org.apache.log4j.Logger;
import org.apache.log4j.spi.LoggingEvent;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.Issue;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.dsl.app.ModelDiagnostic;

/**
 * Bad input gets diagnostics, never a crash: thousands of seeded random and mutated model files
 * (random bytes, random token soup, example models with tokens deleted, duplicated, swapped or
 * replaced, truncated, with binary junk, and one 1 MB nonsense file) are loaded as applications,
 * in batches next to the example class diagrams and actors, so that mutated goals, tasks and
 * states link and reach the validators.
 * No exception may escape, none may be swallowed and logged by Xtext (a crashing check), and every
 * error has a position and a code, both as {@link ModelDiagnostic} and as the validator's raw
 * {@link Issue}. A failure names the seed and case, so it can be replayed.
 */
public class RobustnessTest {
	public static final long SEED = Long.getLong("triad.fuzz.seed", 20261122L);
	static final int CASES = Integer.getInteger("triad.fuzz.cases", 2000);
	static final int BATCH = 20;

	static final List<String> EXTENSIONS = TriadLanguages.EXTENSIONS;
	static final String[] VOCABULARY = { "classdiagram", "class", "abstract", "extends", "enum", "domain", "robot", "world",
			"property", "action", "pre", "post", "goal", "task", "state", "boolean", "int", "double", "String", "true", "false", "{",
			"}", "(", ")", ";", ",", ".", ":", "==", "!=", "<", "<=", ">", ">=", "&&", "||", "!", "=", "Shop", "Place", "Room", "Box",
			"Thing", "DoorState", "OPEN", "Bot", "World", "loc", "adj", "holds", "At", "Go", "p", "r", "x", "0", "42", "3.5", "\"s\"",
			"\"", "//", "/*", "*/", "\n", "\t", "Hospital", "Courier", "IsAt", "\u00e9", "\u0000" };
	private static final Pattern TOKEN = Pattern.compile("\"[^\"\\n]*\"|\\w+|//[^\\n]*|\\S");

	public record Case(String description, String extension, byte[] content) {
	}

	/** Collects what Xtext logs as an error: exceptions it caught inside checks, scoping or linking. */
	static final class ErrorLog extends AppenderSkeleton {
		final List<String> errors = new ArrayList<>();

		@Override
		protected synchronized void append(LoggingEvent event) {
			if (event.getLevel().isGreaterOrEqual(Level.ERROR)) {
				String trace = event.getThrowableStrRep() == null ? "" : String.join("\n", event.getThrowableStrRep());
				errors.add(event.getRenderedMessage() + "\n" + trace);
			}
		}

		@Override
		public void close() {
		}

		@Override
		public boolean requiresLayout() {
			return false;
		}
	}

	@Test
	void randomAndMutatedInputsGiveDiagnosticsNotCrashes(@TempDir Path tmp) throws IOException {
		List<Model> corpus = corpus();
		List<Model> targets = linkTargets(corpus);
		Random random = new Random(SEED);
		ErrorLog log = new ErrorLog();
		Logger.getRootLogger().addAppender(log);
		List<String> problems = new ArrayList<>();
		try {
			List<Case> batch = new ArrayList<>();
			for (int i = 0; i < CASES; i++) {
				batch.add(generate(i, random, corpus));
				if (batch.size() == BATCH || i == CASES - 1) {
					run(tmp.resolve("batch" + i), targets, batch, log, problems);
					batch.clear();
				}
			}
			run(tmp.resolve("huge"), List.of(), List.of(huge(random)), log, problems);
		} finally {
			Logger.getRootLogger().removeAppender(log);
		}
		assertEquals("", String.join("\n", problems.stream().limit(20).toList()), problems.size() + " problems (seed " + SEED + ")");
	}

	public record Model(String name, String extension, String text) {
	}

	/** The unmutated class diagrams and actors of the corpus, which every batch links against. */
	static List<Model> linkTargets(List<Model> corpus) {
		return corpus.stream().filter(m -> m.extension().equals("cd") || m.extension().equals("actor"))
				.collect(java.util.stream.Collectors.toMap(Model::name, m -> m, (a, b) -> a, java.util.LinkedHashMap::new)).values()
				.stream().toList();
	}

	public static List<Model> corpus() throws IOException {
		List<Model> models = new ArrayList<>();
		for (Path dir : List.of(Path.of("..", "models"), Path.of("src", "test", "resources", "rules", "_base"))) {
			try (Stream<Path> files = Files.walk(dir)) {
				for (Path f : files.filter(Files::isRegularFile).sorted().toList()) {
					String name = f.getFileName().toString();
					String ext = name.substring(name.lastIndexOf('.') + 1);
					if (EXTENSIONS.contains(ext)) {
						models.add(new Model(name, ext, Files.readString(f)));
					}
				}
			}
		}
		return models;
	}

	public static Case generate(int index, Random random, List<Model> corpus) {
		String ext = EXTENSIONS.get(random.nextInt(EXTENSIONS.size()));
		int kind = random.nextInt(10);
		if (kind == 0) {
			byte[] bytes = new byte[random.nextInt(400)];
			random.nextBytes(bytes);
			return new Case("#" + index + " random bytes", ext, bytes);
		}
		if (kind <= 2) {
			StringBuilder text = new StringBuilder();
			int n = 1 + random.nextInt(120);
			for (int t = 0; t < n; t++) {
				text.append(VOCABULARY[random.nextInt(VOCABULARY.length)]).append(random.nextInt(4) == 0 ? "\n" : " ");
			}
			return new Case("#" + index + " token soup", ext, text.toString().getBytes(StandardCharsets.UTF_8));
		}
		Model model = corpus.get(random.nextInt(corpus.size()));
		List<String> tokens = new ArrayList<>();
		Matcher m = TOKEN.matcher(model.text());
		while (m.find()) {
			tokens.add(m.group());
		}
		StringBuilder what = new StringBuilder("#" + index + " mutated " + model.extension());
		int mutations = 1 + random.nextInt(4);
		for (int k = 0; k < mutations && !tokens.isEmpty(); k++) {
			int at = random.nextInt(tokens.size());
			switch (random.nextInt(5)) {
				case 0 -> {
					what.append(" delete@").append(at);
					tokens.remove(at);
				}
				case 1 -> {
					what.append(" duplicate@").append(at);
					tokens.add(at, tokens.get(at));
				}
				case 2 -> {
					int other = random.nextInt(tokens.size());
					what.append(" swap@").append(at).append('/').append(other);
					String s = tokens.get(at);
					tokens.set(at, tokens.get(other));
					tokens.set(other, s);
				}
				default -> {
					String replacement = VOCABULARY[random.nextInt(VOCABULARY.length)];
					what.append(" replace@").append(at);
					tokens.set(at, replacement);
				}
			}
		}
		String text = String.join(" ", tokens);
		if (random.nextInt(5) == 0) {
			int cut = random.nextInt(text.length() + 1);
			what.append(" truncate@").append(cut);
			text = text.substring(0, cut);
		}
		byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
		if (random.nextInt(8) == 0) {
			byte[] junk = new byte[1 + random.nextInt(30)];
			random.nextBytes(junk);
			int at = random.nextInt(bytes.length + 1);
			byte[] mixed = new byte[bytes.length + junk.length];
			System.arraycopy(bytes, 0, mixed, 0, at);
			System.arraycopy(junk, 0, mixed, at, junk.length);
			System.arraycopy(bytes, at, mixed, at + junk.length, bytes.length - at);
			what.append(" junk@").append(at);
			bytes = mixed;
		}
		// a mutated model keeps its language most of the time, so that it gets past the parser
		return new Case(what.toString(), random.nextInt(4) == 0 ? ext : model.extension(), bytes);
	}

	static Case huge(Random random) {
		StringBuilder text = new StringBuilder(1 << 20);
		while (text.length() < (1 << 20)) {
			text.append(VOCABULARY[random.nextInt(VOCABULARY.length)]).append(' ');
		}
		return new Case("1 MB of token soup", "goal", text.toString().getBytes(StandardCharsets.UTF_8));
	}

	static void run(Path dir, List<Model> targets, List<Case> cases, ErrorLog log, List<String> problems) throws IOException {
		Files.createDirectories(dir);
		for (Model target : targets) {
			Files.writeString(dir.resolve(target.name()), target.text());
		}
		List<String> names = new ArrayList<>();
		for (int i = 0; i < cases.size(); i++) {
			String name = "m" + i + "." + cases.get(i).extension();
			Files.write(dir.resolve(name), cases.get(i).content());
			names.add(name + " = " + cases.get(i).description());
		}
		String where = "batch " + dir.getFileName() + " " + names;
		int logged = log.errors.size();
		try {
			LoadedApplication app = ApplicationAssembler.load(dir);
			for (ModelDiagnostic d : app.diagnostics()) {
				if (d.line() < 1 || d.column() < 1 || d.code() == null || d.code().isEmpty() || d.message().startsWith("cannot read the file") || d.message().startsWith("cannot check the file")) {
					problems.add(where + ": " + d.format(dir));
				}
			}
			for (Resource r : app.resourceSet().getResources()) {
				if (!(r instanceof XtextResource xr)) {
					continue;
				}
				List<Issue> issues = xr.getResourceServiceProvider().getResourceValidator().validate(r, CheckMode.ALL, CancelIndicator.NullImpl);
				for (Issue issue : issues) {
					if (issue.getSeverity() == Severity.ERROR && (issue.getLineNumber() == null || issue.getLineNumber() < 1
							|| issue.getColumn() == null || issue.getColumn() < 1 || issue.getCode() == null || issue.getCode().isEmpty())) {
						problems.add(where + ": " + r.getURI().lastSegment() + ": raw issue without position or code: " + issue);
					}
				}
			}
		} catch (RuntimeException | StackOverflowError e) {
			problems.add(where + ": " + e);
		}
		for (String error : log.errors.subList(logged, log.errors.size())) {
			problems.add(where + ": logged " + error);
		}
		try (Stream<Path> files = Files.walk(dir)) {
			for (Path p : files.sorted(Comparator.reverseOrder()).toList()) {
				Files.deleteIfExists(p);
			}
		}
	}
}
