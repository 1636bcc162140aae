package org.triad.sim;

import java.util.List;

/** Shared fixtures: the default corridor plan and measurements over traces. */
final class Scenes {
    static final FloorPlan PLAN = FloorPlans.corridorWithRooms();

    private Scenes() {
    }

    static Simulation sim(long seed) {
        return Simulation.builder(PLAN).seed(seed).build();
    }

    /** Largest per-step speed of a robot in the trace, m/s. */
    static double maxStepSpeed(Simulation sim, String robot) {
        List<Vec2> path = sim.trace().robotPath(robot);
        double max = 0;
        for (int i = 1; i < path.size(); i++) {
            max = Math.max(max, path.get(i).distance(path.get(i - 1)) / sim.stepSeconds());
        }
        return max;
    }

    static Vec2 personAt(TraceFrame f, int index) {
        return index < f.personX().length && !Double.isNaN(f.personX()[index])
                ? new Vec2(f.personX()[index], f.personY()[index]) : null;
    }

    static Vec2 robotAt(TraceFrame f, int index) {
        return new Vec2(f.robotX()[index], f.robotY()[index]);
    }
}
