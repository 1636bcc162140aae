package org.triad.examples.hospital.vda5050;

import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;

import org.triad.examples.hospital.HospitalFloor;
import org.triad.vda5050.devices.RemoteDoor;
import org.triad.vda5050.devices.RemoteLift;
import org.triad.examples.hospital.HospitalObjects;
import org.triad.runtime.app.FailureExplaining;
import org.triad.vda5050.master.RemoteAgv;
import org.triad.vda5050.master.TrafficControl;

import generated.hospital.IWorld;
import generated.hospital.domain.Door;
import generated.hospital.domain.Item;
import generated.hospital.domain.Lift;
import generated.hospital.domain.Person;
import generated.hospital.domain.Room;
import generated.hospital.domain.WayPoint;

/**
 * The robotics expert's {@code IWorld} over VDA 5050: corridors are the floor's model edges minus those the
 * AGV reports blocked (information {@code blockedEdge}); items and people are where master control last
 * saw the AGV leave them; a person's walk is an order whose edge carries the action {@code walk}. The building's
 * doors and lift are devices on the broker ({@link RemoteDoor}, {@link RemoteLift}): passing a door asks the building
 * to open it, drives through and asks it to close; a ride calls the cabin, drives in, calls it to the other floor and
 * drives out. A device that refuses, stops between floors or does not answer in time fails the action with that
 * reason ({@link #lastFailure()}), which RefArc puts on Status.
 */
public final class VdaBuilding implements IWorld, FailureExplaining {
    private final RemoteAgv agv;
    private final HospitalFloor floor;
    private final HospitalObjects objects;
    private final HospitalKnowledge knowledge;
    private final BuildingDevices devices;
    /** The doors traffic control keeps (opens on reservation), or none without traffic control. */
    private final java.util.Set<String> keptDoors;
    private final Object failureLock = new Object();
    /** Why the last door or lift action failed on a device (not on the AGV); null after any other outcome. */
    private String deviceFailure;

    /** The fleet's traffic control, or null: under it a ride is a reserved edge of the lift (see {@link #ride}). */
    private final TrafficControl traffic;

    VdaBuilding(RemoteAgv agv, HospitalFloor floor, HospitalObjects objects, HospitalKnowledge knowledge, BuildingDevices devices) {
        this(agv, floor, objects, knowledge, devices, null, java.util.List.of());
    }

    VdaBuilding(RemoteAgv agv, HospitalFloor floor, HospitalObjects objects, HospitalKnowledge knowledge, BuildingDevices devices,
            TrafficControl traffic, java.util.Collection<String> keptDoors) {
        this.traffic = traffic;
        this.keptDoors = java.util.Set.copyOf(keptDoors);
        this.agv = Objects.requireNonNull(agv, "agv");
        this.floor = Objects.requireNonNull(floor, "floor");
        this.objects = Objects.requireNonNull(objects, "objects");
        this.knowledge = Objects.requireNonNull(knowledge, "knowledge");
        this.devices = Objects.requireNonNull(devices, "devices");
    }

    /**
     * A corridor edge the AGV does not report blocked. An edge blocked only by doors that traffic control keeps (opens for
     * the robot its reservation lets through, closes when nobody needs it) is open to plan with: the door is closed now
     * because nobody needed it, and opens when this robot does.
     */
    @Override
    public boolean adj(WayPoint a, WayPoint b) {
        if (!floor.isCorridor(a.name(), b.name())) {
            return false;
        }
        String edge = a.name() + "-" + b.name();
        boolean reported = agv.state().map(s -> s.information("blockedEdge").stream()
                .anyMatch(i -> i.infoReferences().stream().anyMatch(r -> r.referenceValue().equals(edge)))).orElse(false);
        return !reported || !keptDoors.isEmpty() && floor.route(a.name(), b.name()).map(floor::doorsOn)
                .map(doors -> !doors.isEmpty() && keptDoors.containsAll(doors)).orElse(false);
    }

    /** The model edge's route length, metres (as the simulated building's). */
    @Override
    public double distance(WayPoint a, WayPoint b) {
        return org.triad.examples.hospital.SimulatedBuilding.routeLength(floor, a.name(), b.name());
    }

    /** The hospital's dock ({@link org.triad.examples.hospital.HospitalBuilding#DOCK}). */
    @Override
    public boolean dock(WayPoint w) {
        return w.name().equals(org.triad.examples.hospital.HospitalBuilding.DOCK);
    }

    @Override
    public boolean itemAt(Item i, WayPoint w) {
        return knowledge.itemAt(i.name()).map(w.name()::equals).orElse(false);
    }

    /** Whether the person walks their own way ({@link HospitalFloor#WALKING_AHEAD}): then followed, never guided. */
    @Override
    public boolean walksAhead(Person p) {
        return HospitalFloor.WALKING_AHEAD.contains(p.name());
    }

    @Override
    public WayPoint personAt(Person p) {
        return objects.waypoint(knowledge.personAt(p.name()));
    }

    @Override
    public boolean walk(Person p, WayPoint src, WayPoint dst) {
        // under traffic control the courier following the person drives a reserved edge like any move (see passDoor)
        boolean ok = traffic != null ? walkRoute(p, src.name(), dst.name())
                : agv.traverse(src.name(), dst.name(), "walk", Map.of("personId", p.name()));
        if (ok) {
            knowledge.personMoved(p.name(), dst.name());
        }
        return ok;
    }

    /** A walk under traffic control: the models' edge reserved, the lobby's parking lanes before or after it plain drives ({@link LobbyRoutes}). */
    private boolean walkRoute(Person p, String src, String dst) {
        String at = agv.state().map(s -> s.lastNodeId()).orElse(null);
        List<String> route = LobbyRoutes.of(traffic).route(agv.name(), at, src, dst);
        return agv.driveRoute(route, traffic, LobbyRoutes.actions(route, src, dst, new RemoteAgv.EdgeAction("walk", Map.of("personId", p.name()))));
    }

    @Override
    public boolean doorway(Door d, WayPoint a, WayPoint b) {
        return HospitalFloor.isDoorway(d.name(), a.name(), b.name());
    }

    @Override
    public boolean landing(Lift l, WayPoint w) {
        return HospitalFloor.isLanding(l.name(), w.name());
    }

    /** The building opens the door, the AGV drives through, the building closes it behind (a door left open is reported). */
    @Override
    public boolean passDoor(Door d, WayPoint src, WayPoint dst) {
        deviceFailure(null);
        if (!doorway(d, src, dst)) {
            return deviceFailure("door '" + d.name() + "' does not join " + src.name() + " and " + dst.name());
        }
        if (traffic != null && keptDoors.contains(d.name())) {
            // under traffic control the way through the door is reserved like any move, and traffic control opens the door it
            // keeps for the robot granted it (and closes it once nobody needs it). Before, this drove a plain order outside
            // the table: a courier stepped aside into the pharmacy, came out through its door, and the table kept it in the
            // pharmacy while it stood at c0, which the table gave others (the service's benchmark: "reports standing at c0,
            // the map has it at pharmacy", its drives refused until it was put right)
            return agv.driveRoute(List.of(src.name(), dst.name()), traffic);
        }
        RemoteDoor door;
        try {
            door = devices.door(d.name());
        } catch (RuntimeException e) {
            return deviceFailure("door '" + d.name() + "' cannot be reached: " + e.getMessage());
        }
        if (!door.open()) {
            return deviceFailure(door.lastFailure().orElse("door '" + d.name() + "' did not open"));
        }
        boolean through = traffic != null ? agv.driveRoute(List.of(src.name(), dst.name()), traffic) : agv.drive(src.name(), dst.name());
        if (!through) {
            return false;
        }
        if (!door.close()) {
            devices.problem("agv " + agv.name() + " passed door '" + d.name() + "', which stays open: "
                    + door.lastFailure().orElse("it did not close"));
        }
        return true;
    }

    /**
     * The ride from landing {@code src} to landing {@code dst}: the building calls the cabin to src's floor, the AGV drives
     * into it, the cabin carries it to dst's floor and the AGV drives out to dst.
     */
    @Override
    public boolean ride(Lift l, WayPoint src, WayPoint dst) {
        deviceFailure(null);
        Optional<HospitalFloor.LiftLanding> from = HospitalFloor.liftLandingAt(src.name()).filter(x -> x.lift().equals(l.name()));
        Optional<HospitalFloor.LiftLanding> to = HospitalFloor.liftLandingAt(dst.name()).filter(x -> x.lift().equals(l.name()));
        if (from.isEmpty() || to.isEmpty() || from.get().floor() == to.get().floor()) {
            return deviceFailure(src.name() + " and " + dst.name() + " are not landings of lift '" + l.name() + "' on two floors");
        }
        if (traffic != null) {
            // the lift is a resource of the traffic map (HospitalTraffic): the ride from landing to landing is reserved
            // with the cabins, so robots queue for the cabin in the order they asked and it carries its capacity; the
            // AGV rides as its edge action (this simulated building brings the cabin), released only once reserved
            return agv.driveRoute(List.of(src.name(), dst.name()), traffic, "ride", java.util.Map.of("liftId", l.name()));
        }
        RemoteLift lift;
        try {
            lift = devices.lift(l.name());
        } catch (RuntimeException e) {
            return deviceFailure("lift '" + l.name() + "' cannot be reached: " + e.getMessage());
        }
        if (!lift.call(from.get().floor())) {
            return deviceFailure(lift.lastFailure().orElse("lift '" + l.name() + "' did not come"));
        }
        if (!agv.drive(src.name(), from.get().cabin())) {
            return false;
        }
        if (!lift.call(to.get().floor())) {
            return deviceFailure(lift.lastFailure().orElse("lift '" + l.name() + "' did not arrive"));
        }
        return agv.drive(to.get().cabin(), dst.name());
    }

    @Override
    public List<Door> doors() {
        return objects.doors();
    }

    @Override
    public List<Lift> lifts() {
        return objects.lifts();
    }

    @Override
    public List<WayPoint> wayPoints() {
        return objects.corridorWaypoints();
    }

    @Override
    public List<Room> rooms() {
        return objects.rooms();
    }

    @Override
    public List<Item> items() {
        return objects.items();
    }

    @Override
    public List<Person> persons() {
        return objects.people();
    }

    @Override
    public Optional<String> lastFailure() {
        synchronized (failureLock) {
            if (deviceFailure != null) {
                return Optional.of(deviceFailure);
            }
        }
        return agv.lastFailure();
    }

    @Override
    public Optional<org.triad.runtime.app.Failure> lastFailureWithCause() {
        synchronized (failureLock) {
            if (deviceFailure != null) {
                return Optional.of(org.triad.runtime.app.Failure.fault(deviceFailure));
            }
        }
        return agv.lastFailureWithCause(); // a ride under traffic control is a drive: its congestion stays one
    }

    /** Records why a device action failed (null: it did not fail on a device); returns false for the action. */
    private boolean deviceFailure(String why) {
        synchronized (failureLock) {
            deviceFailure = why;
        }
        return false;
    }
}
