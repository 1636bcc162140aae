package org.triad.sim;

import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.BodyFixture;
import org.dyn4j.geometry.Geometry;
import org.dyn4j.geometry.MassType;

/** Factory of dyn4j bodies: frictionless, inelastic, non-rotating discs and static wall boxes. */
final class Bodies {
    private Bodies() {
    }

    static Body wall(Vec2 a, Vec2 b, double thickness) {
        double len = a.distance(b);
        boolean horizontal = Math.abs(a.y() - b.y()) < 1e-9;
        Body body = new Body();
        BodyFixture f = body.addFixture(horizontal ? Geometry.createRectangle(len + thickness, thickness)
                : Geometry.createRectangle(thickness, len + thickness));
        f.setFriction(0);
        f.setRestitution(0);
        body.setMass(MassType.INFINITE);
        Vec2 c = a.plus(b).times(0.5);
        body.translate(c.x(), c.y());
        body.setAtRestDetectionEnabled(false);
        return body;
    }

    static Body disc(double radius, Vec2 at, double density) {
        Body body = new Body();
        BodyFixture f = body.addFixture(Geometry.createCircle(radius), density, 0, 0);
        f.setRestitution(0);
        body.setMass(MassType.FIXED_ANGULAR_VELOCITY);
        body.translate(at.x(), at.y());
        body.setLinearDamping(0);
        body.setAtRestDetectionEnabled(false);
        return body;
    }
}
