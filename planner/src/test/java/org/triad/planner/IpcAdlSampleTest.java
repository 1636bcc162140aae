package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.Problem;

/**
 * The ADL sample of the IPC corpus under src/test/resources/pddl/ipc-adl (see SOURCE.md there):
 * conditional effects, quantified, disjunctive and implied preconditions and goals, derived
 * predicates (optical-telegraphs, philosophers, psr-middle). Every problem is
 * solved and its plan replayed on the lifted domain by {@link PlanValidator}, which applies the
 * PDDL semantics independently of the grounder.
 */
class IpcAdlSampleTest {
    @ParameterizedTest
    @CsvSource({"miconic-simpleadl, s2-0", "miconic-simpleadl, s6-0", "miconic-fulladl, f2-0", "miconic-fulladl, f6-0",
            "schedule, probschedule-2-0", "schedule, probschedule-3-0", "assembly, prob01", "trucks, p01",
            "openstacks-sat08-adl, p01", "airport-adl, p01-airport1-p1", "caldera-sat18-adl, p01",
            "optical-telegraphs, p01-opt2", "philosophers, p02-phil3", "psr-middle, p01-s17-n2-l2-f30", "psr-middle, p06-s37-n3-l3-f30"})
    void solvesAndValidates(String domain, String problem) {
        TriadEngineTest.solveAndValidate(TestProblems.domain("ipc-adl/" + domain + "/domain.pddl"),
                TestProblems.problem("ipc-adl/" + domain + "/" + problem + ".pddl"));
    }

    @ParameterizedTest
    @CsvSource({"miconic-simpleadl, s2-0", "schedule, probschedule-2-0", "airport-adl, p01-airport1-p1"})
    void keepsConditionsOnFluentsAsConditionalEffects(String domain, String problem) {
        Problem p = TestProblems.problem("ipc-adl/" + domain + "/" + problem + ".pddl");
        GroundedProblem.Query q = new GroundedProblem(TestProblems.domain("ipc-adl/" + domain + "/domain.pddl"), p).query(p);
        assertTrue(q.task().hasConditionalEffects, "the samples above exercise the conditional path");
    }

    @Test
    void spiderConditionsOnStaticFactsGroundToPlainOperators() {
        Domain d = TestProblems.domain("ipc-adl/spider-sat18-strips/domain.pddl");
        Problem p = TestProblems.problem("ipc-adl/spider-sat18-strips/p01.pddl");
        GroundedProblem.Query q = new GroundedProblem(d, p).query(p);
        assertTrue(q.unsolvableReason() == null, q.unsolvableReason());
        assertFalse(q.task().hasConditionalEffects, "its when-conditions test static facts only");
    }
}
