package org.triad.sim;

import java.util.List;

/**
 * Local avoidance of moving discs: slow down for anyone in the swept corridor ahead, stop short of
 * them, and sidestep (right-hand side by preference) when there is free floor beside. An agent that
 * yields (people giving way to robots) backs off when it can neither go on nor sidestep, which breaks
 * head-on deadlocks in doorways.
 */
final class Steering {
    private static final double MARGIN = 0.15;
    private static final double STOP_GAP = 0.25;
    private static final double SLOW_GAP = 1.3;

    private Steering() {
    }

    /** Result of avoidance: the adjusted velocity and whether someone obstructs the way. */
    record Avoidance(Vec2 velocity, boolean obstructed) {
    }

    static Avoidance avoid(Agent self, Vec2 desired, List<? extends Agent> others, Agent ignored, boolean yields) {
        double speed = desired.length();
        if (speed < 1e-6) {
            return new Avoidance(desired, false);
        }
        Vec2 dir = desired.times(1 / speed);
        Vec2 left = dir.perpendicular();
        Vec2 p = self.position();
        double factor = 1;
        Vec2 side = Vec2.ZERO;
        boolean obstructed = false;
        boolean ambiguous = true;
        for (Agent o : others) {
            if (o == self || o == ignored || o.body == null) {
                continue;
            }
            Vec2 r = o.position().minus(p);
            double along = r.dot(dir);
            double lateral = r.dot(left);
            double reach = self.radius + o.radius + MARGIN;
            if (along <= 0 || Math.abs(lateral) >= reach) {
                continue;
            }
            double gap = r.length() - self.radius - o.radius;
            if (gap > SLOW_GAP + 0.7) {
                continue;
            }
            obstructed = true;
            factor = Math.min(factor, Math.max(0, Math.min(1, (gap - STOP_GAP) / (SLOW_GAP - STOP_GAP))));
            double away = lateral > 0.05 ? -1 : lateral < -0.05 ? 1 : -1;
            if (Math.abs(lateral) > 0.1) {
                ambiguous = false;
            }
            side = side.plus(left.times(away * (reach - Math.abs(lateral)) / reach));
        }
        if (!obstructed) {
            return new Avoidance(desired, false);
        }
        Vec2 forward = dir.times(speed * factor);
        Vec2 sideDir = side.normalized();
        double probe = self.radius + 0.25;
        if (!sideDir.equals(Vec2.ZERO) && !self.sim.isFree(p.plus(sideDir.times(probe)), self.radius)) {
            sideDir = ambiguous && self.sim.isFree(p.minus(sideDir.times(probe)), self.radius) ? sideDir.times(-1) : Vec2.ZERO;
        }
        if (sideDir.equals(Vec2.ZERO)) {
            return new Avoidance(yields && factor == 0 ? dir.times(-0.4 * self.maxSpeed) : forward, true);
        }
        return new Avoidance(forward.plus(sideDir.times(0.5 * self.maxSpeed)).clampLength(self.maxSpeed), true);
    }
}
