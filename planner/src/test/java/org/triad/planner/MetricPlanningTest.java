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

    /** The roads domain with a visitor the courier can escort along a road (at the road's length too). */
    private static final String ESCORT_DOMAIN = """
            (define (domain escort)
              (:requirements :strips :typing :action-costs :negative-preconditions)
              (:types place parcel visitor)
              (:predicates (at ?p - place) (road ?a ?b - place) (parcel-at ?x - parcel ?p - place) (carries ?x - parcel)
                (visitor-at ?v - visitor ?p - place) (followed ?v - visitor))
              (:functions (length ?a ?b - place) (total-cost))
              (:action move :parameters (?a ?b - place) :precondition (and (at ?a) (road ?a ?b))
                :effect (and (not (at ?a)) (at ?b) (increase (total-cost) (length ?a ?b))))
              (:action escort :parameters (?v - visitor ?a ?b - place) :precondition (and (at ?a) (visitor-at ?v ?a) (road ?a ?b) (not (followed ?v)))
                :effect (and (not (at ?a)) (at ?b) (not (visitor-at ?v ?a)) (visitor-at ?v ?b) (increase (total-cost) (length ?a ?b))))
              (:action follow :parameters (?v - visitor ?p - place) :precondition (and (at ?p) (visitor-at ?v ?p)) :effect (followed ?v))
              (:action pick :parameters (?x - parcel ?p - place) :precondition (and (at ?p) (parcel-at ?x ?p))
                :effect (and (not (parcel-at ?x ?p)) (carries ?x)))
              (:action drop :parameters (?x - parcel ?p - place) :precondition (and (at ?p) (carries ?x))
                :effect (and (not (carries ?x)) (parcel-at ?x ?p))))""";

    private static String escortProblem(String goal) {
        return """
                (define (problem errand) (:domain escort)
                  (:objects lobby store c1 ward - place gauze - parcel alice - visitor)
                  (:init (at lobby) (parcel-at gauze store) (visitor-at alice lobby)
                    (road lobby store) (road store lobby) (road store c1) (road c1 store) (road c1 ward) (road ward c1) (road store ward) (road ward store)
                    (= (length lobby store) 5) (= (length store lobby) 5) (= (length store c1) 2.8) (= (length c1 store) 2.8)
                    (= (length c1 ward) 3.2) (= (length ward c1) 3.2) (= (length store ward) 6) (= (length ward store) 6) (= (total-cost) 0))
                  (:goal %s) (:metric minimize (total-cost)))""".formatted(goal);
    }

    @Test
    void ofTheCheapestPlansTheOneOfFewestStepsIsTaken() {
        Domain d = PddlParser.parseDomain(ESCORT_DOMAIN, "escort.pddl");
        // store -> ward directly (6 m) and through c1 (2.8 + 3.2 m) are equally long: the direct road, one step less
        Problem p = PddlParser.parseProblem(escortProblem("(parcel-at gauze ward)"), "errand.pddl");
        PddlPlan plan = solve(d, p);
        assertEquals(11, PlanValidator.metricValue(d, p, plan).getAsDouble(), 1e-9);
        assertEquals(List.of(PddlStep.of("move", "lobby", "store"), PddlStep.of("pick", "gauze", "store"), PddlStep.of("move", "store", "ward"),
                PddlStep.of("drop", "gauze", "ward")), plan.steps());
        // a goal that needs the visitor: escorting her is the way
        Problem visit = PddlParser.parseProblem(escortProblem("(and (parcel-at gauze ward) (visitor-at alice ward))"), "visit.pddl");
        PddlPlan escorted = solve(d, visit);
        assertEquals(11, PlanValidator.metricValue(d, visit, escorted).getAsDouble(), 1e-9);
        assertEquals(4, escorted.length(), escorted.toPddl());
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
