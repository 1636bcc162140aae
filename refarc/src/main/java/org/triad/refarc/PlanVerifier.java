package org.triad.refarc;

import java.util.Objects;
import java.util.Optional;
import org.triad.runtime.app.Plan;

/**
 * Sits between Planner and Controller of an {@link OpenRefArc}: forwards a plan only if the
 * {@link PlanCheck} does not refute it; a refuted plan reaches the Controller as a planning failure
 * whose reason is the refutation, so the Controller re-plans under its usual budget. Failures and
 * already-satisfied goals pass unchanged. A check that throws counts as a refutation naming the
 * exception: the verifier must answer every result, or the Controller would wait forever.
 */
public class PlanVerifier extends PlanVerifierTOP {
    private final PlanCheck check;

    public PlanVerifier(PlanCheck check) {
        this.check = Objects.requireNonNull(check, "PlanVerifier needs a PlanCheck");
    }

    @Override
    protected void onProposed(PlanResult message) {
        if (message.alreadySatisfied() || !(message.outcome() instanceof PlanningOutcome.Planned p)) {
            verified.send(message);
            return;
        }
        Optional<String> refutation = refute(message, p.plan());
        verified.send(refutation.isEmpty() ? message
                : message.withOutcome(PlanningOutcome.failed("plan refuted: " + refutation.get())));
    }

    private Optional<String> refute(PlanResult message, Plan plan) {
        try {
            return Objects.requireNonNull(check.refute(message.goal(), message.from(), plan), "the PlanCheck returned null");
        } catch (Exception e) {
            return Optional.of("the plan check threw " + e.getClass().getSimpleName() + (e.getMessage() == null ? "" : ": " + e.getMessage()));
        }
    }
}
