package org.triad.building.traffic;

import java.util.function.ToDoubleBiFunction;

import org.triad.runtime.app.DomainObject;
import org.triad.runtime.schema.ActionCosts;

/**
 * Traffic's expected waits as planning costs ({@link org.triad.runtime.schema.GoalSolver#withCosts}): an action
 * of the robot with two waypoint arguments that are joined on the traffic map (a move) costs its expected
 * wait, in steps of {@code secondsPerStep}; a step blocked for good (a lost robot, an obstacle) costs
 * {@link #BLOCKED} steps, so the plan goes round it where it can. Every other action costs nothing extra.
 */
public final class CongestionCosts {
    /** The extra steps of a blocked move: larger than any detour in a building, finite for the planner. */
    public static final double BLOCKED = 1000;

    private CongestionCosts() {
    }

    /**
     * @param map            the traffic map (node ids are the waypoints' names)
     * @param expectedWait   seconds a robot asking now would wait to drive from one node to the other, e.g.
     *                       {@code table::expectedWait} (under the table owner's lock)
     * @param secondsPerStep how many seconds one action stands for (a move's typical time)
     */
    public static ActionCosts of(TrafficMap map, ToDoubleBiFunction<String, String> expectedWait, double secondsPerStep) {
        if (!(secondsPerStep > 0) || Double.isInfinite(secondsPerStep)) {
            throw new IllegalArgumentException("seconds per step is a positive number, not " + secondsPerStep);
        }
        return action -> {
            if (action.args().size() != 2 || !(action.args().get(0) instanceof DomainObject a) || !(action.args().get(1) instanceof DomainObject b)
                    || !map.hasNode(a.name()) || !map.hasNode(b.name()) || map.edge(a.name(), b.name()).isEmpty()) {
                return 0;
            }
            double wait = expectedWait.applyAsDouble(a.name(), b.name());
            return Double.isFinite(wait) ? Math.min(wait / secondsPerStep, BLOCKED) : BLOCKED;
        };
    }
}
