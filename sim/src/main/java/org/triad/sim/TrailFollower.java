package org.triad.sim;

/**
 * Follows another agent along its breadcrumbs, keeping a target distance measured along the trail
 * (so corners do not make the follower stop or lag): speed is the leader's speed plus a proportional
 * term on the distance error, reduced before turns so the follower does not swing into door jambs.
 */
final class TrailFollower {
    private static final double REACHED = 0.35;
    private static final int LOOKAHEAD_POINTS = 5;
    private final Agent self;
    private final Agent leader;
    private int index;

    TrailFollower(Agent self, Agent leader) {
        this.self = self;
        this.leader = leader;
        this.index = Math.max(0, leader.trail.size() - 1);
    }

    /** Distance to the leader along its trail, metres. */
    double trailDistance() {
        Vec2 p = self.position();
        Trail t = leader.trail;
        if (index >= t.size()) {
            return p.distance(leader.position());
        }
        double d = p.distance(t.get(index));
        for (int i = index; i + 1 < t.size(); i++) {
            d += t.get(i).distance(t.get(i + 1));
        }
        return d + t.get(t.size() - 1).distance(leader.position());
    }

    /**
     * Velocity keeping {@code distance} metres behind along the trail, never closer than
     * {@code minDistance} metres in a straight line.
     */
    Vec2 desiredVelocity(double distance, double minDistance) {
        Vec2 p = self.position();
        Trail t = leader.trail;
        while (index < t.size() - 1 && p.distance(t.get(index)) < REACHED) {
            index++;
        }
        Vec2 target = index < t.size() && p.distance(t.get(index)) >= REACHED ? t.get(index) : leader.position();
        double error = trailDistance() - distance;
        if (error <= 0 || p.distance(leader.position()) <= minDistance) {
            return Vec2.ZERO;
        }
        double leaderSpeed = leader.velocity().length();
        double speed = Math.min(leaderSpeed + 1.2 * error, leaderSpeed + Math.sqrt(2 * 0.9 * self.maxAcceleration * error));
        Vec2 ahead = index + LOOKAHEAD_POINTS < t.size() ? t.get(index + LOOKAHEAD_POINTS) : leader.position();
        Vec2 heading = self.velocity().normalized();
        if (!heading.equals(Vec2.ZERO) && ahead.distance(p) > 0.1) {
            double cos = Math.max(0, heading.dot(ahead.minus(p).normalized()));
            speed = Math.min(speed, self.maxSpeed * Math.max(0.35, cos * cos));
        }
        return target.minus(p).normalized().times(Math.min(speed, self.maxSpeed));
    }
}
