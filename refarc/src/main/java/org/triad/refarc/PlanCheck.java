package org.triad.refarc;

import java.util.Optional;
import org.triad.runtime.app.GoalInstance;
import org.triad.runtime.app.Plan;
import org.triad.runtime.app.State;

/** Decides whether a plan may be executed; used by {@link PlanVerifier}. */
@FunctionalInterface
public interface PlanCheck {
    /** Why {@code plan} does not achieve {@code goal} from {@code from}, or empty if it is acceptable. */
    Optional<String> refute(GoalInstance goal, State from, Plan plan) throws Exception;
}
