package org.triad.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.dsl.app.ModelDiagnostic;
import org.triad.dsl.triad.Situation;
import org.triad.generator.SchemaBuilder;
import org.triad.generator.SituationReader;
import org.triad.runtime.app.EnumValue;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.AppSchema;

/**
 * An application loaded for a command: checked, turned into its runtime schema, with a situation
 * chosen and call expressions such as {@code Fetch(gauze, storage, ward3)} read against it.
 */
final class ModelSession {
	final LoadedApplication loaded;
	final AppSchema schema;

	private ModelSession(LoadedApplication loaded) {
		this.loaded = loaded;
		this.schema = SchemaBuilder.build(loaded.application());
	}

	/** Loads and checks an application; model errors end the command with their diagnostics. */
	static ModelSession open(Path dir) {
		if (!Files.isDirectory(dir)) {
			throw new UserError("not a folder: " + dir);
		}
		LoadedApplication app = ApplicationAssembler.load(dir);
		if (app.hasErrors()) {
			StringBuilder b = new StringBuilder("the models have errors (run 'triad check " + dir + "'):");
			for (ModelDiagnostic d : app.diagnostics()) {
				if (d.isError()) {
					b.append("\n").append(d.format(app.root()));
				}
			}
			throw new UserError(b.toString());
		}
		return new ModelSession(app);
	}

	/** The situation in a .state file (its first one, or the one named), or the situation of that name. */
	State situation(String stateArg, String name) {
		List<Situation> candidates = new ArrayList<>();
		Path asFile = Path.of(stateArg);
		for (Situation s : loaded.application().getSituations()) {
			Path file = Path.of(s.eResource().getURI().toFileString());
			boolean fileMatches = stateArg.endsWith(".state")
					&& (file.endsWith(asFile) || file.equals(asFile.toAbsolutePath().normalize()) || file.getFileName().toString().equals(asFile.getFileName().toString()));
			if (fileMatches && (name == null || s.getName().equals(name)) || !stateArg.endsWith(".state") && s.getName().equals(stateArg)) {
				candidates.add(s);
			}
		}
		if (candidates.isEmpty()) {
			List<String> known = loaded.application().getSituations().stream()
					.map(s -> s.getName() + " (" + Path.of(s.eResource().getURI().toFileString()).getFileName() + ")").toList();
			throw new UserError("no situation '" + stateArg + (name == null ? "" : "/" + name) + "' in the application; known: " + known);
		}
		return SituationReader.read(candidates.get(0), schema);
	}

	private static final Pattern CALL = Pattern.compile("\\s*([A-Za-z_][A-Za-z0-9_]*)\\s*\\((.*)\\)\\s*");

	/** A call such as {@code IsAt(ward3)}: its name and its arguments, objects of the state or literals. */
	record Call(String name, List<Object> args) {
	}

	static Call parseCall(String text, State state) {
		Matcher m = CALL.matcher(text);
		if (!m.matches()) {
			throw new UserError("expected Name(arg, ...), got '" + text + "'");
		}
		List<Object> args = new ArrayList<>();
		String inner = m.group(2).trim();
		if (!inner.isEmpty()) {
			for (String raw : inner.split(",")) {
				args.add(value(raw.trim(), state));
			}
		}
		return new Call(m.group(1), args);
	}

	private static Object value(String s, State state) {
		if (s.matches("-?\\d+")) {
			return Integer.parseInt(s);
		}
		if (s.matches("-?\\d+\\.\\d+")) {
			return Double.parseDouble(s);
		}
		if (s.length() >= 2 && s.startsWith("\"") && s.endsWith("\"")) {
			return s.substring(1, s.length() - 1);
		}
		if (s.equals("true") || s.equals("false")) {
			return Boolean.parseBoolean(s);
		}
		if (state.object(s).isPresent()) {
			return state.object(s).get();
		}
		if (s.matches("[A-Za-z_]\\w*\\.[A-Za-z_]\\w*")) {
			String[] parts = s.split("\\.");
			return new EnumValue(parts[0], parts[1]);
		}
		throw new UserError("unknown object '" + s + "'; the situation has " + state.objects().keySet());
	}

	/** A problem with what the user asked for: printed as one line, exit code 2. */
	static final class UserError extends RuntimeException {
		private static final long serialVersionUID = 1L;

		UserError(String message) {
			super(message);
		}
	}
}
