package org.triad.runtime.planning;

import java.time.Duration;
import org.triad.runtime.pddl.Domain;
import org.triad.runtime.pddl.Problem;

/**
 * A pluggable classical planner. Implementations never throw for an unsolvable or malformed
 * problem: they report it in the {@link PlanResult}.
 */
public interface Planner {
    PlanResult solve(Domain domain, Problem problem, Duration timeout);

    /** A short name for logs and tables, e.g. {@code triad}. */
    String name();
}
