package org.triad.dsl;

import java.util.List;
import java.util.Map;

import com.google.inject.Injector;

/**
 * The Triad modeling languages, set up together because their models link to each other: an
 * actor refers to the class diagram's types, a task to goals, a goal to actors' properties; the
 * architecture (.arc) files of an application are checked alongside.
 */
public final class TriadLanguages {
	/** The file extensions of model files, in the order an application is usually read. */
	public static final List<String> EXTENSIONS = List.of("cd", "actor", "goal", "task", "state", "arc");

	private static Map<String, Injector> injectors;

	private TriadLanguages() {
	}

	/** Registers every language (idempotent) and returns the injector of each, by file extension. */
	public static synchronized Map<String, Injector> setup() {
		if (injectors == null) {
			injectors = Map.of(
					"cd", new TriadCdStandaloneSetup().createInjectorAndDoEMFRegistration(),
					"actor", new TriadActorStandaloneSetup().createInjectorAndDoEMFRegistration(),
					"goal", new TriadGoalStandaloneSetup().createInjectorAndDoEMFRegistration(),
					"task", new TriadTaskStandaloneSetup().createInjectorAndDoEMFRegistration(),
					"state", new TriadStateStandaloneSetup().createInjectorAndDoEMFRegistration(),
					"arc", new TriadArcStandaloneSetup().createInjectorAndDoEMFRegistration());
		}
		return injectors;
	}

	/** The injector of the class-diagram language; any language's injector serves to create resource sets. */
	public static Injector anyInjector() {
		return setup().get("cd");
	}
}
