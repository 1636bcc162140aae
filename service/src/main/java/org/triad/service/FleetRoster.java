package org.triad.service;

import java.util.ArrayList;
import java.util.List;

import org.triad.building.SharedWorld;
import org.triad.refarc.fleet.FleetChanges;
import org.triad.refarc.fleet.FleetRobot;

/**
 * The service's {@link FleetChanges}: robots that providers report joining, leaving or refused while the
 * service runs go to the {@link FleetService}; what is reported before the service has one (while the
 * providers connect) waits and is applied in order when it is {@link #attach attached}. A joining robot
 * becomes a member of the building's world, as the robots given at start do.
 */
final class FleetRoster implements FleetChanges {
    private SharedWorld world;
    private FleetService fleet;
    private List<Runnable> pending = new ArrayList<>();

    synchronized void building(SharedWorld world) {
        this.world = world;
    }

    /** From now on changes go to {@code fleet}; those reported so far are applied now, in order. */
    synchronized void attach(FleetService fleet) {
        this.fleet = fleet;
        List<Runnable> waiting = pending;
        pending = null;
        waiting.forEach(Runnable::run);
    }

    @Override
    public void joined(FleetRobot robot) {
        apply(() -> {
            if (!robot.name().matches("[A-Za-z0-9_-]+")) {
                fleet.refuseRobot(robot.name().replaceAll("[^A-Za-z0-9_-]", "_"), "its name '" + robot.name() + "' is not letters, digits, '-' and '_'");
            } else if (fleet.hasRobot(robot.name())) {
                fleet.join(robot);
            } else {
                fleet.join(world.observing(robot));
            }
        });
    }

    @Override
    public void left(String name, String reason) {
        apply(() -> fleet.leave(name, reason));
    }

    @Override
    public void refused(String name, String reason) {
        apply(() -> fleet.refuseRobot(name, reason));
    }

    private synchronized void apply(Runnable change) {
        if (pending != null) {
            pending.add(change);
        } else {
            try {
                change.run();
            } catch (RuntimeException e) {
                // the provider's thread must go on reporting; the operator page shows what did apply
                System.err.println("triad serve: a robot change failed: " + e);
            }
        }
    }
}
