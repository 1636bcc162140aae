package org.triad.sim;

/**
 * Follows another agent along its breadcrumbs, keeping a target distance: speed is the leader's
 * speed plus a proportional term on the distance error, braking so it never closes in below the target.
 */
final class TrailFollower {
    private final Agent self;
    private final Agent leader;
    private int index;

    TrailFollower(Agent self, Agent leader) {
        this.self = self;
        this.leader = leader;
        this.index = Math.max(0, leader.trail.size() - 1);
    }

    Vec2 desiredVelocity(double distance) {
        Vec2 p = self.position();
        Trail t = leader.trail;
        while (index < t.size() - 1 && p.distance(t.get(index)) < 0.35) {
            index++;
        }
        Vec2 target = index < t.size() && p.distance(t.get(index)) >= 0.35 ? t.get(index) : leader.position();
        double d = p.distance(leader.position());
        double error = d - distance;
        if (error <= 0) {
            return Vec2.ZERO;
        }
        double speed = leader.velocity().length() + 1.2 * error;
        speed = Math.min(speed, Math.sqrt(2 * 0.9 * self.maxAcceleration * error) + leader.velocity().length());
        return target.minus(p).normalized().times(Math.min(speed, self.maxSpeed));
    }
}
