package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParseException;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.PlanMetric;
import org.triad.planner.pddl.Problem;

/**
 * {@code (:metric minimize|maximize ...)}: the engine returns the cheapest plan it finds by the metric,
 * not the shortest, for action costs (classical) and for any expression over numeric fluents; without a
 * metric it stays with the shortest. Every plan is replayed by {@link PlanValidator} and its metric
 * valued by {@link PlanValidator#metricValue}.
 */
class MetricPlanningTest {
    private static final Duration TIMEOUT = Duration.ofSeconds(120);

    private static PddlPlan solve(Domain d, Problem p) {
        SolveResult r = new TriadEngine().solve(d, p, TIMEOUT);
        assertEquals(SolveResult.Status.SOLVED, r.status(), r.message());
        PlanValidator.Report report = PlanValidator.validate(d, p, r.plan());
        assertTrue(report.valid(), report.message() + "\n" + r.plan().toPddl());
        return r.plan();
    }

    private static Problem withoutMetric(String path) {
        return PddlParser.parseProblem(TestProblems.text(path).replace("(:metric minimize (total-cost))", ""), path);
    }

    @Test
    void aRouteIsTheShortestInMetresNotInSteps() {
        Domain d = TestProblems.domain("metric/roads-domain.pddl");
        Problem p = TestProblems.problem("metric/roads-route.pddl");
        PddlPlan cheapest = solve(d, p);
        assertEquals(List.of(PddlStep.of("move", "lobby", "c1"), PddlStep.of("move", "c1", "c2"), PddlStep.of("move", "c2", "ward")), cheapest.steps());
        assertEquals(30, PlanValidator.metricValue(d, p, cheapest).getAsDouble());
        // without a metric, fewest steps
        assertEquals(List.of(PddlStep.of("move", "lobby", "ward")), solve(d, withoutMetric("metric/roads-route.pddl")).steps());
    }

    @Test
    void aDeliveryTakesTheCheapestRoadsThereAndBack() {
        Domain d = TestProblems.domain("metric/roads-domain.pddl");
        Problem p = TestProblems.problem("metric/roads-delivery.pddl");
        PddlPlan plan = solve(d, p);
        // 15 to the store, pick, 10 to the ward, drop, 25 back to the lobby (the direct roads: 162)
        assertEquals(52, PlanValidator.metricValue(d, p, plan).getAsDouble(), plan.toPddl());
        PddlPlan shortest = solve(d, withoutMetric("metric/roads-delivery.pddl"));
        assertTrue(shortest.length() < plan.length(), shortest.toPddl());
    }

    @Test
    void aNumericMetricIsMinimised() {
        // the battery domain with a direct road of 70 m: fewest steps take it, least travelled the corridor (60 m)
        Domain d = TestProblems.domain("numeric/battery-domain.pddl");
        String text = TestProblems.text("numeric/battery-problem.pddl").replace("(= (battery r1) 30)", "(= (battery r1) 90)")
                .replace("(road lobby dock)", "(road lobby dock) (road lobby ward) (= (distance lobby ward) 70)");
        Problem p = PddlParser.parseProblem(text, "direct.pddl");
        PddlPlan plan = solve(d, p);
        assertEquals(3, plan.length(), plan.toPddl());
        assertEquals(60, PlanValidator.metricValue(d, p, plan).getAsDouble());
        PddlPlan steps = solve(d, PddlParser.parseProblem(text.replace("(:metric minimize (travelled))", ""), "direct.pddl"));
        assertEquals(1, steps.length(), steps.toPddl());
    }

    @Test
    void aMaximisedFluentIsMadeLarge() {
        // with a large battery, recharging on the way leaves the most charge at the ward
        Domain d = TestProblems.domain("numeric/battery-domain.pddl");
        String text = TestProblems.text("numeric/battery-problem.pddl").replace("(= (battery r1) 30)", "(= (battery r1) 90)")
                .replace("(= (capacity r1) 100)", "(= (capacity r1) 200)");
        PddlPlan most = solve(d, PddlParser.parseProblem(text.replace("minimize (travelled)", "maximize (battery r1)"), "max.pddl"));
        assertTrue(most.steps().contains(PddlStep.of("recharge", "r1", "dock")), most.toPddl());
        PddlPlan least = solve(d, PddlParser.parseProblem(text, "min.pddl"));
        assertFalse(least.steps().contains(PddlStep.of("recharge", "r1", "dock")), least.toPddl());
    }

    @Test
    void aMetricIsReadAndABadOneIsALocatedError() {
        PlanMetric m = PlanMetric.of(TestProblems.problem("metric/roads-route.pddl"));
        assertTrue(m.isTotalCost());
        assertEquals("minimize (total-cost)", m.toString());
        String bad = TestProblems.text("metric/roads-route.pddl").replace("(:metric minimize (total-cost))", "(:metric minimise (total-cost))");
        PddlParseException e = assertThrows(PddlParseException.class, () -> PddlParser.parseProblem(bad, "bad.pddl"));
        assertEquals(11, e.line(), e.getMessage());
        assertTrue(e.getMessage().contains("expected '(:metric minimize EXPRESSION)'"), e.getMessage());
        String variable = bad.replace("minimise (total-cost)", "minimize (length ?a lobby)");
        assertTrue(assertThrows(PddlParseException.class, () -> PddlParser.parseProblem(variable, "bad.pddl")).getMessage()
                .contains("variable '?a' in the metric"));
    }
}
