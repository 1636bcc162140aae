package org.triad.dsl.app;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.JarURLConnection;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.jar.JarFile;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.URI;
import org.triad.dsl.TriadLanguages;

/**
 * Model libraries on the class path: every model file below a {@code triad-models/} folder of a jar
 * or class folder, e.g. RefArc's components ({@code triad-models/refarc/OpenRefArc.arc} in the refarc
 * jar). An application's architecture links against them the way the Maven build links it against
 * RefArc's models, without a path to RefArc's sources.
 */
public final class ModelLibraries {
	/** The class-path folder libraries ship their model files in. */
	public static final String FOLDER = "triad-models";

	private ModelLibraries() {
	}

	/** Every library model file on the class path of this class's loader, in a stable order. */
	public static List<URI> onClassPath() {
		return onClassPath(ModelLibraries.class.getClassLoader());
	}

	/** Every library model file on the class path of {@code loader}, in a stable order. */
	public static List<URI> onClassPath(ClassLoader loader) {
		List<URI> result = new ArrayList<>();
		try {
			for (URL root : Collections.list(loader.getResources(FOLDER))) {
				if (root.getProtocol().equals("file")) {
					result.addAll(inFolder(Path.of(root.toURI())));
				} else if (root.getProtocol().equals("jar")) {
					JarURLConnection connection = (JarURLConnection) root.openConnection();
					result.addAll(inJar(Path.of(connection.getJarFileURL().toURI())));
				}
			}
		} catch (IOException e) {
			throw new UncheckedIOException("cannot read the model libraries on the class path: " + e.getMessage(), e);
		} catch (URISyntaxException e) {
			throw new IllegalStateException(e);
		}
		return result;
	}

	/**
	 * The library model files in a jar (below its {@code triad-models/} folder), e.g. a dependency a
	 * Gradle or Maven build hands the assembler.
	 */
	public static List<URI> inJar(Path jar) {
		String base = jar.toAbsolutePath().normalize().toUri().toString();
		try (JarFile file = new JarFile(jar.toFile())) {
			return file.stream().map(e -> e.getName()).filter(n -> n.startsWith(FOLDER + "/") && isModel(Path.of(n))).sorted()
					.map(n -> URI.createURI("jar:" + base + "!/" + n)).toList();
		} catch (IOException e) {
			throw new UncheckedIOException("cannot read the model library " + jar + ": " + e.getMessage(), e);
		}
	}

	private static List<URI> inFolder(Path dir) throws IOException {
		try (Stream<Path> files = Files.walk(dir)) {
			return files.filter(Files::isRegularFile).filter(ModelLibraries::isModel).sorted().map(f -> URI.createFileURI(f.toString()))
					.toList();
		}
	}

	/** A library file's path below {@code triad-models/}, e.g. {@code refarc/OpenRefArc.arc}. */
	public static String relativePath(URI library) {
		String s = library.toString();
		int at = s.lastIndexOf("/" + FOLDER + "/");
		return at < 0 ? s : s.substring(at + FOLDER.length() + 2);
	}

	private static boolean isModel(Path p) {
		return TriadLanguages.EXTENSIONS.contains(ApplicationAssembler.extension(p));
	}
}
