package org.triad.sim;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;

/**
 * A walking person (disc body). Behaviours are non-blocking: set one and advance the simulation.
 * People route around doors that are currently closed and sidestep others like the robot.
 */
public final class Person extends Agent {
    private static final double YIELD_LOOKAHEAD = 2.5;
    private Behaviour behaviour = new Stand();
    private boolean present = true;
    private boolean yieldsToRobots = true;

    Person(Simulation sim, String name, PersonSpec spec) {
        super(sim, name, spec.radius(), spec.maxSpeed(), spec.maxAcceleration());
    }

    /** Walks along the waypoint graph to {@code waypoint}; {@link #isWalking()} turns false on arrival. */
    public void walkTo(String waypoint) {
        sim.plan().waypoint(waypoint);
        behaviour = new Walk(waypoint);
    }

    /** Follows {@code leader} along its trail, stopping {@code distance} metres behind it. */
    public void follow(Agent leader, double distance) {
        Checks.notNull("leader", leader);
        Checks.positive("follow distance (m)", distance);
        behaviour = new Follow(leader, distance);
    }

    /** Stops and stays. */
    public void standStill() {
        behaviour = new Stand();
    }

    /**
     * Walks forever to random waypoints (from the simulation's seeded generator, excluding waypoints in
     * doorways), pausing 1-4 s at each.
     */
    public void wander() {
        behaviour = new Wander();
    }

    /** Whether a walk is still under way (false when standing, following, or arrived). */
    public boolean isWalking() {
        return behaviour instanceof Walk w && !w.done || behaviour instanceof Wander;
    }

    /** Whether the person is still in the world (scripted blockers leave). */
    public boolean isPresent() {
        return present;
    }

    /** The room the person is in, if any. */
    public Optional<Room> room() {
        return sim.plan().roomAt(position());
    }

    /**
     * Whether the person steps out of the way of a robot coming towards them (default true). People who
     * block a corridor on purpose do not.
     */
    public void setYieldsToRobots(boolean yields) {
        this.yieldsToRobots = yields;
    }

    public boolean yieldsToRobots() {
        return yieldsToRobots;
    }

    void leave() {
        present = false;
    }

    @Override
    void control(double dt) {
        Vec2 desired = behaviour.desired();
        Vec2 escape = yieldsToRobots ? escapeFromRobots() : null;
        if (escape != null) {
            drive(escape, dt);
            return;
        }
        // People only steer around robots; among themselves contact physics lets them squeeze past,
        // which avoids crowd gridlock at popular waypoints.
        Steering.Avoidance a = Steering.avoid(this, desired, sim.robots(), behaviour.ignored(), true);
        drive(a.velocity(), dt);
    }

    /** A velocity that leaves the path of an approaching robot, or null if no robot needs the space. */
    private Vec2 escapeFromRobots() {
        Vec2 p = position();
        for (Robot r : sim.robots()) {
            Vec2 d = r.intendedDirection();
            if (d.equals(Vec2.ZERO) || r.partner() == this) {
                continue;
            }
            Vec2 rel = p.minus(r.position());
            double along = rel.dot(d);
            double lateral = rel.dot(d.perpendicular());
            if (along < -0.2 || along > YIELD_LOOKAHEAD || Math.abs(lateral) >= r.radius + radius + 0.25) {
                continue;
            }
            Vec2 side = d.perpendicular().times(lateral >= -0.05 ? 1 : -1);
            double probe = radius + 0.3;
            if (sim.isFree(p.plus(side.times(probe)), radius)) {
                return side.times(0.6 * maxSpeed);
            }
            if (sim.isFree(p.minus(side.times(probe)), radius) && Math.abs(lateral) < 0.3) {
                return side.times(-0.6 * maxSpeed);
            }
            return d.times(maxSpeed);
        }
        return null;
    }

    private interface Behaviour {
        Vec2 desired();

        default Agent ignored() {
            return null;
        }
    }

    private final class Stand implements Behaviour {
        @Override
        public Vec2 desired() {
            return Vec2.ZERO;
        }
    }

    private final class Walk implements Behaviour {
        private final PathFollower follower;
        private boolean done;

        Walk(String goal) {
            Set<String> closed = new TreeSet<>();
            sim.doors().stream().filter(d -> !d.isOpen()).forEach(d -> closed.add(d.name()));
            List<Vec2> via = new ArrayList<>();
            sim.planner().route(position(), goal, closed, radius)
                    .ifPresent(r -> r.forEach(n -> via.add(sim.plan().waypoint(n).position())));
            if (via.isEmpty()) {
                done = true;
            }
            follower = via.isEmpty() ? null : new PathFollower(sim.plan(), position(), via, 0.15);
        }

        @Override
        public Vec2 desired() {
            if (done || follower.arrived(position())) {
                done = true;
                return Vec2.ZERO;
            }
            return follower.desiredVelocity(position(), maxSpeed, maxAcceleration);
        }
    }

    private final class Follow implements Behaviour {
        private final Agent leader;
        private final TrailFollower follower;
        private final double distance;

        Follow(Agent leader, double distance) {
            this.leader = leader;
            this.distance = distance;
            this.follower = new TrailFollower(Person.this, leader);
        }

        @Override
        public Vec2 desired() {
            return follower.desiredVelocity(distance, distance * 0.6);
        }

        @Override
        public Agent ignored() {
            return leader;
        }
    }

    private final class Wander implements Behaviour {
        private Walk walk;
        private double pauseUntil = -1;

        @Override
        public Vec2 desired() {
            if (walk == null || walk.done) {
                if (pauseUntil < 0) {
                    pauseUntil = sim.time() + 1 + 3 * sim.random().nextDouble();
                }
                if (sim.time() >= pauseUntil) {
                    List<Waypoint> wps = sim.wanderTargets();
                    walk = new Walk(wps.get(sim.random().nextInt(wps.size())).name());
                    pauseUntil = -1;
                } else {
                    return Vec2.ZERO;
                }
            }
            return walk.desired();
        }
    }
}
