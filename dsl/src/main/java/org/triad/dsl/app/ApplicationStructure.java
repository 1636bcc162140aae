package org.triad.dsl.app;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.triad.dsl.triad.Actor;
import org.triad.dsl.triad.ActorKind;
import org.triad.dsl.triad.ClassDiagram;
import org.triad.dsl.validation.ActorIssueCodes;
import org.triad.dsl.validation.CommonIssueCodes;

/**
 * The rule every Triad application obeys, in one place: exactly one class diagram (it names the
 * application), exactly one robot actor and exactly one world actor (codes
 * {@code app.class-diagram-count}, {@code app.robot-count}/{@code app.world-count} when one is missing,
 * {@code actor.duplicate-kind} on every actor of a kind that has several). {@link ApplicationAssembler}
 * builds the application from it and the validators report its violations, so the command line,
 * the language server and the Maven and Gradle builds see the same application and the same findings.
 *
 * @param classDiagrams every class diagram of the application, in a stable order (by resource URI)
 * @param robots        every robot actor, in the same order
 * @param worlds        every world actor, in the same order
 */
public record ApplicationStructure(List<ClassDiagram> classDiagrams, List<Actor> robots, List<Actor> worlds) {
	/** A broken rule, attached to the model element the editor should underline. */
	public record Violation(EObject element, String code, String message) {
	}

	private static final Comparator<EObject> STABLE = Comparator.comparing(e -> EcoreUtil.getURI(e).toString());

	/** The structure formed by the class diagrams and actors among {@code elements} (anything else is ignored). */
	public static ApplicationStructure of(Iterable<? extends EObject> elements) {
		List<ClassDiagram> cds = new ArrayList<>();
		List<Actor> robots = new ArrayList<>();
		List<Actor> worlds = new ArrayList<>();
		boolean architecture = false;
		for (EObject e : elements) {
			if (e instanceof org.triad.dsl.arc.ComponentType) {
				architecture = true;
			} else if (e instanceof ClassDiagram cd) {
				cds.add(cd);
			} else if (e instanceof Actor a) {
				(a.getKind() == ActorKind.ROBOT ? robots : worlds).add(a);
			}
		}
		if (architecture && robots.isEmpty() && worlds.isEmpty()) {
			// class diagrams beside components and no actor: the data types of an architecture (MontiArc's .cd), not an application
			return new ApplicationStructure(List.of(), List.of(), List.of());
		}
		cds.sort(STABLE);
		robots.sort(STABLE);
		worlds.sort(STABLE);
		return new ApplicationStructure(List.copyOf(cds), List.copyOf(robots), List.copyOf(worlds));
	}

	/** The application's class diagram (the first one if the rule is broken), or null. */
	public ClassDiagram classDiagram() {
		return classDiagrams.isEmpty() ? null : classDiagrams.get(0);
	}

	public Actor robot() {
		return robots.isEmpty() ? null : robots.get(0);
	}

	public Actor world() {
		return worlds.isEmpty() ? null : worlds.get(0);
	}

	/** The application's name: its class diagram's name, wherever its files are. */
	public String applicationName() {
		return classDiagram() == null ? null : classDiagram().getName();
	}

	/** Whether the structure holds anything an application rule applies to (a folder of .arc models holds nothing). */
	public boolean isEmpty() {
		return classDiagrams.isEmpty() && robots.isEmpty() && worlds.isEmpty();
	}

	/** Every broken rule; empty when the application has one class diagram, one robot and one world. */
	public List<Violation> violations() {
		List<Violation> result = new ArrayList<>();
		if (isEmpty()) {
			return result;
		}
		ClassDiagram cd = classDiagram();
		if (cd == null) {
			for (Actor a : concat(robots, worlds)) {
				result.add(new Violation(a, CommonIssueCodes.CLASS_DIAGRAM_COUNT,
						"the application has no class diagram (a .cd file with 'classdiagram Name { ... }')"));
			}
		}
		for (ClassDiagram extra : classDiagrams.subList(Math.min(1, classDiagrams.size()), classDiagrams.size())) {
			result.add(new Violation(extra, CommonIssueCodes.CLASS_DIAGRAM_COUNT,
					"the application has more than one class diagram: '" + extra.getName() + "' and '" + cd.getName() + "'"));
		}
		EObject anchor = cd != null ? cd : concat(robots, worlds).get(0);
		actorRule(result, robots, "robot", CommonIssueCodes.ROBOT_COUNT, anchor);
		actorRule(result, worlds, "world", CommonIssueCodes.WORLD_COUNT, anchor);
		return result;
	}

	private static void actorRule(List<Violation> result, List<Actor> actors, String kind, String code, EObject anchor) {
		if (actors.isEmpty()) {
			result.add(new Violation(anchor, code,
					"the application has no " + kind + " (an .actor file with '" + kind + " Name { ... }')"));
		}
		for (Actor actor : actors.size() > 1 ? actors : List.<Actor>of()) {
			Actor other = actors.get(actor == actors.get(0) ? 1 : 0);
			result.add(new Violation(actor, ActorIssueCodes.DUPLICATE_KIND, "an application has one " + kind + ", but '" + other.getName()
					+ "' in " + other.eResource().getURI().lastSegment() + " is one too"));
		}
	}

	private static List<Actor> concat(List<Actor> a, List<Actor> b) {
		List<Actor> all = new ArrayList<>(a);
		all.addAll(b);
		return all;
	}
}
