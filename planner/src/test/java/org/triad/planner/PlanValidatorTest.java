package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.Problem;

class PlanValidatorTest {
    private final Domain domain = TestProblems.domain("hospital/domain.pddl");
    private final Problem problem = TestProblems.problem("hospital/p-10-a.pddl");

    @Test
    void reportsFirstFailingStepWithReason() {
        PddlPlan plan = new PddlPlan(List.of(PddlStep.of("move", "wp0", "wp1"), PddlStep.of("move", "wp0", "wp3")));
        PlanValidator.Report r = PlanValidator.validate(domain, problem, plan);
        assertFalse(r.valid());
        assertEquals(1, r.failedStep());
        assertEquals("step 2 (move wp0 wp3): precondition not satisfied: (robot-at wp0) is false", r.message());
    }

    @Test
    void reportsTypeErrorsUnknownActionsAndMissingGoal() {
        assertTrue(PlanValidator.validate(domain, problem, new PddlPlan(List.of(PddlStep.of("load", "wp1", "wp0")))).message()
                .contains("'wp1' is not of type item for ?i"));
        assertTrue(PlanValidator.validate(domain, problem, new PddlPlan(List.of(PddlStep.of("fly", "wp1")))).message()
                .contains("unknown action 'fly'"));
        PlanValidator.Report r = PlanValidator.validate(domain, problem, new PddlPlan(List.of(PddlStep.of("move", "wp0", "wp1"))));
        assertFalse(r.goalReached());
        assertTrue(r.message().startsWith("goal not satisfied at the end: (robot-at r1) is false"), r.message());
    }

    @Test
    void acceptsAValidPlan() {
        PddlPlan plan = new PddlPlan(List.of(PddlStep.of("move", "wp0", "wp3"), PddlStep.of("move", "wp3", "wp6"),
                PddlStep.of("move", "wp6", "r1")));
        assertTrue(PlanValidator.validate(domain, problem, plan).valid());
    }
}
