package org.triad.cli;

import java.io.IOException;
import java.io.InputStream;
import java.net.JarURLConnection;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Enumeration;
import java.util.Map;
import java.util.TreeMap;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;
import java.util.stream.Stream;

/**
 * Triad's Maven archetype ({@code archetype/}: {@code archetype-resources/} and its descriptor) read from
 * the class path and written out as {@code mvn archetype:generate} would: the archetype's own templates use
 * only the property references replaced here ({@code ${appName}}, {@code ${appName.toLowerCase()}},
 * {@code ${package}}, {@code ${groupId}}, {@code ${artifactId}}, {@code ${version}}, {@code ${triadVersion}}),
 * {@code __appName__} in file names, and Java sources go below their package's folder.
 */
final class ArchetypeProject {
	static final String ROOT = "archetype-resources/";
	/** The Triad version a new project builds against: this toolchain's own. */
	static final String TRIAD_VERSION = "0.1.0-SNAPSHOT";

	record Properties(String appName, String groupId, String artifactId, String version, String javaPackage, String triadVersion) {
		String substitute(String text) {
			return text.replace("${appName.toLowerCase()}", appName.toLowerCase(java.util.Locale.ROOT)).replace("${appName}", appName)
					.replace("${package}", javaPackage).replace("${groupId}", groupId).replace("${artifactId}", artifactId)
					.replace("${version}", version).replace("${triadVersion}", triadVersion);
		}
	}

	/** The archetype's files by their path below {@code archetype-resources/}. */
	private final Map<String, byte[]> files;

	private ArchetypeProject(Map<String, byte[]> files) {
		this.files = files;
	}

	static ArchetypeProject fromClassPath(ClassLoader loader) throws IOException {
		URL pom = loader.getResource(ROOT + "pom.xml");
		if (pom == null) {
			throw new IllegalStateException("Triad's archetype (triad-archetype) is not on the class path");
		}
		Map<String, byte[]> files = new TreeMap<>();
		if (pom.getProtocol().equals("jar")) {
			JarURLConnection connection = (JarURLConnection) pom.openConnection();
			connection.setUseCaches(false);
			try (JarFile jar = connection.getJarFile()) {
				for (Enumeration<JarEntry> entries = jar.entries(); entries.hasMoreElements();) {
					JarEntry e = entries.nextElement();
					if (!e.isDirectory() && e.getName().startsWith(ROOT)) {
						try (InputStream in = jar.getInputStream(e)) {
							files.put(e.getName().substring(ROOT.length()), in.readAllBytes());
						}
					}
				}
			}
		} else {
			Path root;
			try {
				root = Path.of(pom.toURI()).getParent();
			} catch (URISyntaxException e) {
				throw new IOException(e);
			}
			try (Stream<Path> walk = Files.walk(root)) {
				for (Path p : walk.filter(Files::isRegularFile).toList()) {
					files.put(root.relativize(p).toString().replace('\\', '/'), Files.readAllBytes(p));
				}
			}
		}
		return new ArchetypeProject(files);
	}

	/** Writes the project into {@code dir}; returns the number of files written. */
	int generate(Path dir, Properties properties) throws IOException {
		for (Map.Entry<String, byte[]> f : files.entrySet()) {
			Path target = dir.resolve(targetPath(f.getKey(), properties));
			Files.createDirectories(target.getParent());
			Files.writeString(target, properties.substitute(new String(f.getValue(), StandardCharsets.UTF_8)), StandardCharsets.UTF_8);
		}
		return files.size();
	}

	private static String targetPath(String path, Properties properties) {
		String p = path.replace("__appName__", properties.appName());
		for (String sourceRoot : new String[] { "src/main/java/", "src/test/java/" }) {
			if (p.startsWith(sourceRoot)) {
				return sourceRoot + properties.javaPackage().replace('.', '/') + "/" + p.substring(sourceRoot.length());
			}
		}
		return p;
	}

	/** Whether the user's local Maven repository (~/.m2/repository) has Triad's artifacts a new project needs. */
	static boolean triadArtifactsInstalled() {
		Path repo = Path.of(System.getProperty("user.home"), ".m2", "repository", "org", "triad");
		return Stream.of("triad-refarc", "triad-generator").allMatch(a -> Files.isDirectory(repo.resolve(a).resolve(TRIAD_VERSION)));
	}
}
