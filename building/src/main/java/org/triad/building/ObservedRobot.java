package org.triad.building;

import java.util.Optional;

import org.triad.refarc.ActionRunner;
import org.triad.refarc.StateSource;
import org.triad.refarc.fleet.FleetRobot;
import org.triad.refarc.fleet.FloorMap;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.State;

/**
 * A robot with a platform of its own (simulator, AGV) as a member of a {@link SharedWorld}: it plans
 * on the building's world with its own robot-actor values as the platform reports them, and what its
 * platform reports changed in the world while it acted is written into the building.
 */
final class ObservedRobot implements FleetRobot, BuildingMember {
    private final SharedWorld world;
    private final FleetRobot robot;
    private final StateSource view;
    private final ActionRunner runner;

    /**
     * @param wholeBuilding whether the robot's platform observes the whole building: then what changed there since
     *                      the building's last report is written into the world at every report, else only what
     *                      changed while this robot acted
     */
    ObservedRobot(SharedWorld world, FleetRobot robot, boolean wholeBuilding) {
        this.world = world;
        this.robot = robot;
        StateSource ownState = robot.stateSource();
        this.view = wholeBuilding ? () -> world.follow(ownState) : world.view(ownState);
        ActionRunner own = robot.actionRunner();
        this.runner = new ActionRunner() {
            @Override
            public Optional<String> violatedPrecondition(GroundAction action, State now) throws Exception {
                return own.violatedPrecondition(action, now);
            }

            @Override
            public boolean execute(GroundAction action) throws Exception {
                if (wholeBuilding) {
                    boolean ok = own.execute(action);
                    world.follow(ownState);
                    return ok;
                }
                State before = ownState.currentState();
                boolean ok = own.execute(action);
                world.observe(before, ownState.currentState());
                return ok;
            }

            @Override
            public Optional<String> failureReason(GroundAction action) {
                return own.failureReason(action);
            }

            @Override
            public Optional<org.triad.runtime.app.Failure> failure(GroundAction action) {
                return own.failure(action);
            }
        };
    }

    @Override
    public SharedWorld world() {
        return world;
    }

    @Override
    public String name() {
        return robot.name();
    }

    @Override
    public StateSource stateSource() {
        return view;
    }

    @Override
    public ActionRunner actionRunner() {
        return runner;
    }

    @Override
    public Optional<FloorMap> floor() {
        return robot.floor();
    }

    @Override
    public java.util.Map<String, FloorMap> floors() {
        return robot.floors();
    }

    @Override
    public Optional<org.triad.refarc.fleet.Pose> pose() {
        return robot.pose();
    }

    @Override
    public Optional<org.triad.refarc.fleet.Battery> battery() {
        return robot.battery();
    }

    /** The platform's own way out of the others' way (an observed robot moves as its platform does). */
    @Override
    public Optional<String> parkOutOfTheWay() {
        return robot.parkOutOfTheWay();
    }

    @Override
    public void close() {
        robot.close();
    }
}
