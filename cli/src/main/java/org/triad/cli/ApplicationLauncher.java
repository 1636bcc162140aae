package org.triad.cli;

import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.io.Reader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;

import org.triad.runtime.app.LauncherWatch;
import org.triad.vda5050.security.ClientCredentials;

/**
 * Runs code an application provides (its demo, its robot, its simulated fleet) without the command
 * line depending on the application: an application project names its mains in
 * {@code src/main/resources/META-INF/triad/application.properties} (key: the {@code triad} command,
 * e.g. {@code demo=org.triad.examples.hospital.HospitalDemo}), its build writes its class path to
 * {@code target/classpath.txt} (maven-dependency-plugin {@code build-classpath}), and the launcher
 * starts {@code java -cp target/classes:<classpath> <main> <args>} in a child JVM, forwarding the
 * output and the exit code.
 */
final class ApplicationLauncher {
	static final String DESCRIPTOR = "META-INF/triad/application.properties";

	private final Path project;

	ApplicationLauncher(Path project) {
		this.project = project.toAbsolutePath().normalize();
	}

	/** The application project {@code triad} ships with, e.g. {@code models/hospital} below the Triad checkout. */
	static ApplicationLauncher bundled(String relative) {
		return new ApplicationLauncher(Path.of(System.getProperty("triad.home", ".")).resolve(relative));
	}

	/** The main class the application provides for {@code command}. */
	String mainClass(String command) {
		Path descriptor = project.resolve("target/classes").resolve(DESCRIPTOR);
		if (!Files.isRegularFile(descriptor)) {
			throw new ModelSession.UserError("the application in " + project + " is not built (no " + project.relativize(descriptor)
					+ "); build it with 'mvn -B -q -DskipTests -pl " + project.getFileName() + " -am package' or run ./triad, which builds it");
		}
		Properties p = new Properties();
		try (Reader r = Files.newBufferedReader(descriptor, StandardCharsets.UTF_8)) {
			p.load(r);
		} catch (IOException e) {
			throw new UncheckedIOException("cannot read " + descriptor + ": " + e.getMessage(), e);
		}
		String main = p.getProperty(command);
		if (main == null || main.isBlank()) {
			throw new ModelSession.UserError("the application in " + project + " provides no '" + command + "' (" + DESCRIPTOR + " names "
					+ p.stringPropertyNames() + ")");
		}
		return main.trim();
	}

	/**
	 * The application's classes (its {@code target/classes} and the class path its build wrote), for
	 * plug-ins found with {@link java.util.ServiceLoader} in this JVM, e.g. its simulated robots for
	 * {@code triad serve}; empty when the project is not built. Triad's own classes come from the parent.
	 */
	java.util.Optional<ClassLoader> classLoader(ClassLoader parent) {
		Path classes = project.resolve("target/classes");
		Path classpathFile = project.resolve("target/classpath.txt");
		if (!Files.isDirectory(classes) || !Files.isRegularFile(classpathFile)) {
			return java.util.Optional.empty();
		}
		List<java.net.URL> urls = new ArrayList<>();
		try {
			urls.add(classes.toUri().toURL());
			for (String entry : Files.readString(classpathFile).trim().split(java.io.File.pathSeparator)) {
				if (!entry.isBlank()) {
					urls.add(Path.of(entry).toUri().toURL());
				}
			}
		} catch (IOException e) {
			throw new UncheckedIOException("cannot read " + classpathFile + ": " + e.getMessage(), e);
		}
		return java.util.Optional.of(new java.net.URLClassLoader(urls.toArray(java.net.URL[]::new), parent));
	}

	/** Runs the application's {@code command} with {@code args}; returns its exit code. */
	int run(String command, List<String> args, PrintWriter out, PrintWriter err) {
		String main = mainClass(command);
		Path classpathFile = project.resolve("target/classpath.txt");
		if (!Files.isRegularFile(classpathFile)) {
			throw new ModelSession.UserError("the application in " + project + " has no target/classpath.txt; build it with 'mvn -B -q -DskipTests -pl "
					+ project.getFileName() + " -am package'");
		}
		List<String> cmd = new ArrayList<>();
		cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
		String opts = System.getenv("TRIAD_JAVA_OPTS");
		if (opts != null && !opts.isBlank()) {
			cmd.addAll(List.of(opts.trim().split("\\s+")));
		}
		// the broker credentials of --credentials reach the application's MQTT connections
		String credentials = System.getProperty(ClientCredentials.PROPERTY);
		if (credentials != null) {
			cmd.add("-D" + ClientCredentials.PROPERTY + "=" + credentials);
		}
		cmd.add("-cp");
		try {
			cmd.add(project.resolve("target/classes") + java.io.File.pathSeparator + Files.readString(classpathFile).trim());
		} catch (IOException e) {
			throw new UncheckedIOException("cannot read " + classpathFile + ": " + e.getMessage(), e);
		}
		// the child ends with this process: stopped by the hook below, or (SIGKILL) by its own LauncherWatch
		cmd.add("-D" + LauncherWatch.PROPERTY + "=" + ProcessHandle.current().pid());
		cmd.add(main);
		cmd.addAll(args);
		try {
			Process process = new ProcessBuilder(cmd).redirectInput(ProcessBuilder.Redirect.INHERIT).start();
			Thread stopChild = new Thread(() -> stop(process), "stop-" + command);
			Runtime.getRuntime().addShutdownHook(stopChild);
			Thread errors = copy(process.getErrorStream(), err);
			copy(process.getInputStream(), out).join();
			errors.join();
			int code = process.waitFor();
			try {
				Runtime.getRuntime().removeShutdownHook(stopChild);
			} catch (IllegalStateException e) {
				// shutting down: the hook runs and finds the child ended
			}
			return code;
		} catch (IOException e) {
			throw new UncheckedIOException("cannot start " + main + ": " + e.getMessage(), e);
		} catch (InterruptedException e) {
			Thread.currentThread().interrupt();
			throw new IllegalStateException("interrupted while " + main + " ran", e);
		}
	}

	/** SIGTERM (the child's shutdown hooks run: a robot reports OFFLINE), SIGKILL after 10 s. */
	private static void stop(Process child) {
		if (!child.isAlive()) {
			return;
		}
		child.destroy();
		try {
			if (!child.waitFor(10, java.util.concurrent.TimeUnit.SECONDS)) {
				child.destroyForcibly().waitFor(5, java.util.concurrent.TimeUnit.SECONDS);
			}
		} catch (InterruptedException e) {
			child.destroyForcibly();
			Thread.currentThread().interrupt();
		}
	}

	private static Thread copy(InputStream from, PrintWriter to) {
		Thread t = new Thread(() -> {
			try (Reader r = new InputStreamReader(from, StandardCharsets.UTF_8)) {
				char[] buffer = new char[4096];
				for (int n; (n = r.read(buffer)) >= 0;) {
					to.write(buffer, 0, n);
					to.flush();
				}
			} catch (IOException e) {
				to.println("triad: lost the application's output: " + e.getMessage());
			}
		}, "application-output");
		t.setDaemon(true);
		t.start();
		return t;
	}
}
