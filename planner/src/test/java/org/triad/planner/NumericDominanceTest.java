package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

/**
 * Which fluents are resources whose more (or less) is never worse ({@link NumericDominance}): a battery
 * that moves need and a dock refills, a load under a payload limit; and the cases where no such order
 * holds, which must not prune anything.
 */
class NumericDominanceTest {

    private static NumericTask hospital(String domainEdit, String from, String to) {
        Domain d = PddlParser.parseDomain(NumericHospitalBenchmark.DOMAIN.replace(from, to) + domainEdit, "hospital.pddl");
        NumericHospitalBenchmark.MapGrid m = NumericHospitalBenchmark.MapGrid.of(9, 3);
        Problem p = PddlParser.parseProblem(NumericHospitalBenchmark.problem(m, new NumericHospitalBenchmark.Goal("g", 0, 30, 4, 8)), "p.pddl");
        return new NumericTask(d, p);
    }

    private static int direction(NumericTask task, NumericDominance dominance, String fluent) {
        return dominance.direction[task.fluentNames.indexOf(fluent)];
    }

    @Test
    void aBatteryIsBetterFullAndALoadLighter() {
        NumericTask task = hospital("", "", "");
        NumericDominance dominance = NumericDominance.of(task);
        assertTrue(dominance.any);
        // the recharge's guard (< (battery) (capacity)) assigns the capacity itself: no reason to prefer less charge
        assertEquals(NumericDominance.MORE_IS_BETTER, direction(task, dominance, "battery"));
        assertEquals(NumericDominance.LESS_IS_BETTER, direction(task, dominance, "load"));
        // the metric's accumulator is compared as the cost, not as a resource
        assertEquals(NumericDominance.NEITHER, direction(task, dominance, "total-cost"));
        double[] full = task.initValues.clone();
        double[] low = task.initValues.clone();
        low[task.fluentNames.indexOf("battery")] -= 5;
        assertTrue(dominance.covers(full, low));
        assertFalse(dominance.covers(low, full));
    }

    @Test
    void aRechargeThatOnlyHelpsBelowHalfMakesLessChargeUseful() {
        // a dock that tops up to 60 only when the battery is under 30: at 40 the robot cannot recharge, at 20 it can
        NumericTask task = hospital("", "(< (battery) (capacity))", "(< (battery) 30)");
        assertEquals(NumericDominance.NEITHER, direction(task, NumericDominance.of(task), "battery"));
    }

    @Test
    void aFluentReadByAnEffectHasNoOrder() {
        // the cost of a move grows with the charge carried: more charge is no longer free
        NumericTask task = hospital("", "(increase (total-cost) (distance ?src ?dst))", "(increase (total-cost) (battery))");
        assertEquals(NumericDominance.NEITHER, direction(task, NumericDominance.of(task), "battery"));
    }
}
