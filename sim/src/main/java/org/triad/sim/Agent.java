package org.triad.sim;

import org.dyn4j.dynamics.Body;

/**
 * Common state of robots and people: a disc (dyn4j body) whose velocity a controller sets each step,
 * within its speed (m/s) and acceleration (m/s^2) bounds. Only {@link Robot} and {@link Person} extend it.
 */
public abstract class Agent {
    final Simulation sim;
    final String name;
    final double radius;
    final double maxSpeed;
    final double maxAcceleration;
    final Trail trail = new Trail();
    Body body;

    Agent(Simulation sim, String name, double radius, double maxSpeed, double maxAcceleration) {
        this.sim = sim;
        this.name = name;
        this.radius = radius;
        this.maxSpeed = maxSpeed;
        this.maxAcceleration = maxAcceleration;
    }

    /** Name given when added to the simulation. */
    public String name() {
        return name;
    }

    /** Current centre position, metres. */
    public Vec2 position() {
        return new Vec2(body.getWorldCenter().x, body.getWorldCenter().y);
    }

    /** Current velocity, m/s. */
    public Vec2 velocity() {
        return new Vec2(body.getLinearVelocity().x, body.getLinearVelocity().y);
    }

    /** Body radius, metres. */
    public double radius() {
        return radius;
    }

    /** Speed bound, m/s. */
    public double maxSpeed() {
        return maxSpeed;
    }

    /** Sets the velocity for the next step, limited by the acceleration and speed bounds. */
    void drive(Vec2 desired, double dt) {
        Vec2 v = velocity();
        Vec2 next = v.plus(desired.minus(v).clampLength(maxAcceleration * dt)).clampLength(maxSpeed);
        body.setLinearVelocity(next.x(), next.y());
    }

    abstract void control(double dt);

    void afterStep() {
        trail.record(position());
    }
}
