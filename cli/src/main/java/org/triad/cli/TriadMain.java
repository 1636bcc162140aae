package org.triad.cli;

import java.io.File;
import java.io.PrintWriter;
import java.lang.reflect.InvocationTargetException;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Path;

import org.triad.planner.PddlPlanner;
import org.triad.planner.PddlPlanners;

/**
 * The {@code ./triad} launcher's entry. A plain {@code triad solve} runs straight away, without
 * picocli, Xtext or EMF (which set up every command by reflection, and whose signed jars the JVM
 * verifies and cannot keep in a class-data archive); every other command line goes to {@link TriadCli}.
 * For {@code solve} the launcher puts only this jar and the planner's on the class path (a JDK 25 JVM
 * with an AOT cache opens every jar of its class path at start-up) and names the whole class path in
 * the system property {@value #CLASS_PATH}, on which a {@code solve} that needs picocli then runs.
 */
public final class TriadMain {
	/** The system property with the CLI's whole class path, when the JVM runs on a part of it. */
	static final String CLASS_PATH = "triad.classpath";

	private TriadMain() {
	}

	public static void main(String[] args) {
		if (args.length > 0 && args[0].equals("solve")) {
			SolveArguments a = SolveArguments.parse(args);
			PddlPlanner engine = a == null ? null : planner(a.planner);
			if (engine != null) {
				PrintWriter out = new PrintWriter(System.out, true);
				PrintWriter err = new PrintWriter(System.err, true);
				int exit;
				try {
					exit = new SolveRun(a.domain, a.problem, a.plan, engine, a.timeoutSeconds, a.seed).run(out, err);
				} catch (RuntimeException e) {
					// as TriadCli's execution exception handler reports it
					err.println("triad solve: " + FailureMessage.of(e));
					exit = 2;
				}
				System.exit(exit);
			}
		}
		String whole = System.getProperty(CLASS_PATH);
		if (whole == null || whole.equals(System.getProperty("java.class.path"))) {
			TriadCli.main(args);
		} else {
			onWholeClassPath(whole, args);
		}
	}

	/** {@link TriadCli#main} in a class loader of the whole class path (every class loaded anew from it). */
	private static void onWholeClassPath(String classPath, String[] args) {
		String[] entries = classPath.split(File.pathSeparator);
		URL[] urls = new URL[entries.length];
		try {
			for (int i = 0; i < entries.length; i++) {
				urls[i] = Path.of(entries[i]).toUri().toURL();
			}
		} catch (MalformedURLException e) {
			throw new IllegalStateException("bad class path entry in " + CLASS_PATH + ": " + e.getMessage(), e);
		}
		System.setProperty("java.class.path", classPath);
		ClassLoader loader = new URLClassLoader(urls, ClassLoader.getPlatformClassLoader());
		Thread.currentThread().setContextClassLoader(loader);
		try {
			loader.loadClass("org.triad.cli.TriadCli").getMethod("main", String[].class).invoke(null, (Object) args);
		} catch (InvocationTargetException e) {
			if (e.getCause() instanceof RuntimeException r) {
				throw r;
			}
			if (e.getCause() instanceof Error r) {
				throw r;
			}
			throw new IllegalStateException(e.getCause());
		} catch (ReflectiveOperationException e) {
			throw new IllegalStateException("cannot start the command line from " + CLASS_PATH + ": " + e, e);
		}
	}

	/** The planner named, or null for a name picocli's command reports as a usage error. */
	private static PddlPlanner planner(String name) {
		try {
			return PddlPlanners.byName(name);
		} catch (IllegalArgumentException e) {
			return null;
		}
	}
}
