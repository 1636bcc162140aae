package org.triad.planner;

import java.time.Duration;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.Problem;

/**
 * A pluggable classical planner. Implementations never throw for an unsolvable or malformed
 * problem: they report it in the {@link SolveResult}.
 */
public interface PddlPlanner {
    SolveResult solve(Domain domain, Problem problem, Duration timeout);

    /** A short name for logs and tables, e.g. {@code triad}. */
    String name();
}
