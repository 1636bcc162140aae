package org.triad.dsl.semantics;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import org.triad.dsl.triad.Situation;

/** What {@code state B extends A} means: B is A's objects and facts, then B's own, which override A's. */
public final class SituationLineage {
	private SituationLineage() {
	}

	/**
	 * The situation and those it extends, nearest first ({@code B, A} for {@code state B extends A}); stops
	 * before an unresolved parent and at a cycle, which the validator reports ({@code state.extends-cycle}).
	 */
	public static List<Situation> lineage(Situation situation) {
		Set<Situation> seen = new LinkedHashSet<>();
		for (Situation s = situation; s != null && !s.eIsProxy() && seen.add(s); s = s.getParent()) {
			// collecting
		}
		return new ArrayList<>(seen);
	}

	/** The situations whose facts make up this one, in the order they apply: the farthest ancestor first. */
	public static List<Situation> applicationOrder(Situation situation) {
		List<Situation> order = lineage(situation);
		Collections.reverse(order);
		return order;
	}

	/** Whether following {@code extends} from the situation comes back to it. */
	public static boolean extendsItself(Situation situation) {
		Set<Situation> seen = new LinkedHashSet<>();
		for (Situation s = situation.getParent(); s != null && !s.eIsProxy() && seen.add(s); s = s.getParent()) {
			if (s == situation) {
				return true;
			}
		}
		return false;
	}
}
