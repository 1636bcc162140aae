package org.triad.planner.pddl;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;
import org.triad.planner.TestProblems;

class PddlWriterTest {
    @ParameterizedTest
    @ValueSource(strings = {"hospital/domain.pddl", "ipc/blocks/domain.pddl", "ipc/depot/domain.pddl",
            "ipc/elevators/p01-domain.pddl", "ipc/gripper/domain.pddl", "ipc/logistics00/domain.pddl", "ipc/miconic/domain.pddl",
            "numeric/battery-domain.pddl", "numeric/counters-domain.pddl"})
    void domainRoundTrips(String path) {
        Domain d = TestProblems.domain(path);
        String text = PddlWriter.write(d);
        assertEquals(d, PddlParser.parseDomain(text, "written"));
        assertEquals(text, PddlWriter.write(PddlParser.parseDomain(text, "written")));
    }

    @ParameterizedTest
    @ValueSource(strings = {"hospital/p-10-c.pddl", "ipc/blocks/probBLOCKS-4-0.pddl", "ipc/elevators/p01.pddl",
            "ipc/logistics00/problogistics-10-0.pddl", "numeric/battery-problem.pddl", "numeric/counters-problem.pddl"})
    void problemRoundTrips(String path) {
        Problem p = TestProblems.problem(path);
        assertEquals(p, PddlParser.parseProblem(PddlWriter.write(p), "written"));
    }

    @Test
    void writesProgrammaticModelsWithQuantifiersAndEither() {
        Formula pre = new Formula.And(List.of(Formula.Atom.of("at", "?r"),
                new Formula.Forall(List.of(new TypedName("?x", List.of("a", "b"))), new Formula.Imply(Formula.Atom.of("p", "?x"), new Formula.Not(new Formula.Equals("?x", "?r"))))));
        Action act = new Action("go", List.of(TypedName.of("?r", "a")), pre,
                List.of(new PddlEffect.Delete(Formula.Atom.of("at", "?r")), new PddlEffect.Increase("total-cost", new NumericTerm.Constant(2))));
        Domain d = new Domain("built", List.of(":adl"), List.of(TypedName.of("a", "object"), TypedName.of("b", "object")), List.of(),
                List.of(new PredicateDecl("at", List.of(TypedName.of("?r", "a"))), new PredicateDecl("p", List.of(new TypedName("?x", List.of("a", "b"))))),
                List.of(new PredicateDecl("total-cost", List.of())), List.of(act));
        String text = PddlWriter.write(d);
        assertEquals(d, PddlParser.parseDomain(text, "built"));
        assertEquals(true, text.contains("(forall (?x - (either a b)) (imply (p ?x) (not (= ?x ?r))))"), text);
    }

    @Test
    void numbersArePlainDecimalsThatOtherPlannersRead() {
        // Double.toString would write 1.0E20 and 1.5E-7, which Metric-FF, ENHSP and VAL do not read
        assertEquals("100000000000000000000", PddlWriter.number(1e20));
        assertEquals("0.00000015", PddlWriter.number(1.5e-7));
        assertEquals("2.5", PddlWriter.number(2.5));
        assertEquals("-7", PddlWriter.number(-7));
        assertEquals(1e20, Double.parseDouble(PddlWriter.number(1e20)));
        org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class, () -> PddlWriter.number(Double.NaN));
    }
}
