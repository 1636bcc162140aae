package org.triad.sim;

import java.util.Locale;

/** Keeps a distance band behind a walking person, along the person's trail. */
final class FollowActivity extends Activity {
    private final Person person;
    private final TrailFollower follower;
    private final double min;
    private final double max;
    private double deadline;
    private double farSince = -1;

    FollowActivity(Robot robot, Person person, double min, double max, double timeout) {
        super(robot, "follow(" + person.name() + ")");
        this.person = person;
        this.follower = new TrailFollower(robot, person);
        this.min = min;
        this.max = max;
        this.deadline = start + timeout;
    }

    @Override
    Agent partner() {
        return person;
    }

    @Override
    void shift(double seconds) {
        deadline += seconds;
        farSince = farSince < 0 ? farSince : farSince + seconds;
    }

    @Override
    void control(double dt) {
        double now = robot.sim.time();
        double d = person.position().distance(robot.position());
        if (!person.isPresent()) {
            fail(Failure.PERSON_LOST, "person '" + person.name() + "' left");
            return;
        }
        if (!person.isWalking() && d <= max) {
            succeed(String.format(Locale.ROOT, "'%s' stopped %.2f m away", person.name(), d));
            return;
        }
        if (now > deadline) {
            fail(Failure.TIMEOUT, String.format(Locale.ROOT, "still following '%s' after %.1f s", person.name(),
                    now - start));
            return;
        }
        if (d > max + 3) {
            farSince = farSince < 0 ? now : farSince;
            if (now - farSince > Robot.LOST_SECONDS) {
                fail(Failure.PERSON_LOST, String.format(Locale.ROOT, "person '%s' is %.1f m away", person.name(), d));
                return;
            }
        } else {
            farSince = -1;
        }
        robot.drive(robot.avoid(follower.desiredVelocity((min + max) / 2, min), person), dt);
    }
}
