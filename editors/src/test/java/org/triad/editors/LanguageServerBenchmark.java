package org.triad.editors;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.DidChangeTextDocumentParams;
import org.eclipse.lsp4j.DidOpenTextDocumentParams;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializedParams;
import org.eclipse.lsp4j.TextDocumentContentChangeEvent;
import org.eclipse.lsp4j.TextDocumentItem;
import org.eclipse.lsp4j.VersionedTextDocumentIdentifier;

/**
 * The language server as an editor meets it, on the hospital application and on 10x and 100x as
 * many models (renamed copies, so they do not clash): the packaged jar is started as a process,
 * and the benchmark measures the time until the workspace is built (initialize answered), from
 * opening a task file to its diagnostics, from a change to its diagnostics (median), and the
 * server's resident memory; medians of three server runs (the change time of a run is the median
 * of its 20 changes). Not a test: run it and read the table.
 *
 * <pre>
 * mvn -B -pl editors -am verify -DskipTests
 * java -cp editors/target/triad-language-server.jar:editors/target/test-classes org.triad.editors.LanguageServerBenchmark [COPIES...]
 * </pre>
 */
public final class LanguageServerBenchmark {
	private static final Path HOSPITAL = Path.of("models/hospital/src/main/models");
	private static final Path JAR = Path.of("editors/target/triad-language-server.jar");
	private static final int RUNS = 3;
	private static final int CHANGES = 20; // even: the last change repairs the file again
	private static final Pattern TOP_LEVEL = Pattern.compile("\\b(?:classdiagram|robot|world|goal|task|state)\\s+([A-Za-z_]\\w*)");

	private LanguageServerBenchmark() {
	}

	public static void main(String[] args) throws Exception {
		List<Integer> scales = args.length == 0 ? List.of(1, 10, 100) : Arrays.stream(args).map(Integer::valueOf).toList();
		System.out.println("| models (copies of the hospital) | files | server start to workspace built (initialize), ms | open -> diagnostics, ms"
				+ " | change -> diagnostics, ms | server RSS, MB | errors found |");
		System.out.println("|---|---|---|---|---|---|---|");
		for (int copies : scales) {
			Path workspace = Files.createTempDirectory("triad-lsp-bench");
			try {
				int files = populate(workspace, copies);
				List<Run> runs = new ArrayList<>();
				for (int r = 0; r < RUNS; r++) {
					runs.add(measure(workspace));
				}
				System.out.println(String.format("| %dx | %d | %d | %d | %.1f | %d | %d |", copies, files, median(runs, Run::builtMs), median(runs, Run::openMs),
						runs.stream().mapToDouble(Run::changeMs).sorted().toArray()[RUNS / 2], median(runs, Run::rssMb), runs.get(0).errors()));
			} finally {
				try (Stream<Path> all = Files.walk(workspace)) {
					all.sorted((a, b) -> b.getNameCount() - a.getNameCount()).forEach(p -> p.toFile().delete());
				}
			}
		}
	}

	/** Copies the hospital's models {@code copies} times, each copy's top-level names suffixed with its number. */
	static int populate(Path workspace, int copies) throws Exception {
		List<Path> sources;
		try (Stream<Path> s = Files.list(HOSPITAL)) {
			sources = s.filter(Files::isRegularFile).sorted().toList();
		}
		Set<String> names = new LinkedHashSet<>();
		for (Path f : sources) {
			Matcher m = TOP_LEVEL.matcher(Files.readString(f).replaceAll("//[^\n]*", ""));
			while (m.find()) {
				names.add(m.group(1));
			}
		}
		int files = 0;
		for (int i = 0; i < copies; i++) {
			Path dir = Files.createDirectories(workspace.resolve("copy" + i));
			for (Path f : sources) {
				String text = Files.readString(f);
				if (i > 0) {
					for (String n : names) {
						text = text.replaceAll("\\b" + n + "\\b", n + i);
					}
				}
				Files.writeString(dir.resolve(f.getFileName()), text);
				files++;
			}
		}
		return files;
	}

	/** One server run's figures; change is the median over its changes. */
	record Run(long builtMs, long openMs, double changeMs, long rssMb, int errors) {
	}

	private static long median(List<Run> runs, java.util.function.ToLongFunction<Run> f) {
		return runs.stream().mapToLong(f).sorted().toArray()[runs.size() / 2];
	}

	private static Run measure(Path workspace) throws Exception {
		long start = System.nanoTime();
		Process process = new ProcessBuilder("java", "-Xmx2g", "-jar", JAR.toAbsolutePath().toString())
				.redirectError(ProcessBuilder.Redirect.DISCARD).start();
		try (LspProcessClient client = new LspProcessClient(process)) {
			InitializeParams init = new InitializeParams();
			init.setProcessId((int) ProcessHandle.current().pid());
			init.setRootUri(workspace.toUri().toString());
			init.setCapabilities(new ClientCapabilities());
			client.server().initialize(init).get(10, TimeUnit.MINUTES);
			long built = System.nanoTime();
			client.server().initialized(new InitializedParams());

			Path tasks = workspace.resolve("copy0/Tasks.task");
			String uri = tasks.toUri().toString().replaceFirst("^file:/(?!/)", "file:///");
			String text = Files.readString(tasks);
			int before = client.publications(uri);
			long openStart = System.nanoTime();
			client.server().getTextDocumentService().didOpen(new DidOpenTextDocumentParams(new TextDocumentItem(uri, "task", 1, text)));
			client.awaitPublication(uri, before);
			long opened = System.nanoTime();

			String broken = text.replaceFirst("IsAt\\(", "IsAtt(");
			List<Long> changes = new ArrayList<>();
			for (int v = 2; v < 2 + CHANGES; v++) {
				String next = v % 2 == 0 ? broken : text;
				int count = client.publications(uri);
				long t = System.nanoTime();
				client.server().getTextDocumentService().didChange(new DidChangeTextDocumentParams(new VersionedTextDocumentIdentifier(uri, v),
						List.of(new TextDocumentContentChangeEvent(next))));
				client.awaitPublication(uri, count);
				changes.add(System.nanoTime() - t);
			}
			changes.sort(null);
			long rssKb = rssKb(process.pid());
			List<String> errorList = client.errors();
			int errors = errorList.size();
			errorList.stream().limit(5).forEach(e -> System.err.println("error in the benchmark's models: " + e));
			client.server().shutdown().get(1, TimeUnit.MINUTES);
			client.server().exit();
			process.waitFor(30, TimeUnit.SECONDS);
			return new Run(ms(built - start), ms(opened - openStart), changes.get(changes.size() / 2) / 1e6, rssKb / 1024, errors);
		} finally {
			process.destroyForcibly();
		}
	}

	private static long ms(long nanos) {
		return TimeUnit.NANOSECONDS.toMillis(nanos);
	}

	/** The process's resident set size from /proc (Linux), or -1. */
	private static long rssKb(long pid) {
		try {
			for (String line : Files.readAllLines(Path.of("/proc/" + pid + "/status"))) {
				if (line.startsWith("VmRSS:")) {
					return Long.parseLong(line.replaceAll("\\D", ""));
				}
			}
		} catch (Exception e) {
			return -1;
		}
		return -1;
	}
}
