package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

/**
 * The sample of the IPC corpus under src/test/resources/pddl/ipc (see SOURCE.md there), chosen for
 * what the parser must handle: names glued to variables (zenotravel), {@code either} types (ged,
 * storage), domain constants (childsnack, parcprinter), capitals and action costs (parcprinter).
 * Every problem is solved and its plan replayed on the lifted domain. The whole corpus is checked
 * by planner/scripts/check-ipc-corpus.sh.
 */
class IpcSampleTest {
    @ParameterizedTest
    @CsvSource({"zenotravel/domain.pddl, zenotravel/p01.pddl", "zenotravel/domain.pddl, zenotravel/p02.pddl",
            "ged-sat14-strips/domain.pddl, ged-sat14-strips/d-3-6.pddl", "storage/domain.pddl, storage/p01.pddl",
            "parcprinter-08-strips/p01-domain.pddl, parcprinter-08-strips/p01.pddl",
            "childsnack-sat14-strips/domain.pddl, childsnack-sat14-strips/child-snack_pfile05.pddl",
            "visitall-sat11-strips/domain.pddl, visitall-sat11-strips/problem12.pddl",
            "freecell/domain.pddl, freecell/probfreecell-2-3.pddl", "tpp/domain.pddl, tpp/p01.pddl"})
    void solvesAndValidates(String domain, String problem) {
        TriadEngineTest.solveAndValidate(TestProblems.domain("ipc/" + domain), TestProblems.problem("ipc/" + problem));
    }

    @Test
    void zenotravelNeedsTheGluedVariablesSplit() {
        Domain d = TestProblems.domain("ipc/zenotravel/domain.pddl");
        Problem p = TestProblems.problem("ipc/zenotravel/p01.pddl");
        SolveResult r = new TriadEngine().solve(d, p, Duration.ofSeconds(30));
        assertTrue(r.isSolved(), r.message());
        assertEquals(d, PddlParser.parseDomain(TestProblems.text("ipc/zenotravel/domain.pddl").replace("?", " ?"), "spaced.pddl"));
    }
}
