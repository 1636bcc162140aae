package org.triad.examples.hospital.vda5050;

import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;

import org.triad.examples.hospital.HospitalFloor;
import org.triad.examples.hospital.HospitalObjects;
import org.triad.runtime.app.FailureExplaining;
import org.triad.vda5050.master.RemoteAgv;

import generated.hospital.IWorld;
import generated.hospital.domain.Item;
import generated.hospital.domain.Person;
import generated.hospital.domain.Room;
import generated.hospital.domain.WayPoint;

/**
 * The robotics expert's {@code IWorld} over VDA 5050: corridors are the floor's model edges minus those the
 * AGV reports blocked (information {@code blockedEdge}); items and people are where master control last
 * saw the AGV leave them; a person's walk is an order whose edge carries the action {@code walk}.
 */
public final class VdaBuilding implements IWorld, FailureExplaining {
    private final RemoteAgv agv;
    private final HospitalFloor floor;
    private final HospitalObjects objects;
    private final HospitalKnowledge knowledge;

    VdaBuilding(RemoteAgv agv, HospitalFloor floor, HospitalObjects objects, HospitalKnowledge knowledge) {
        this.agv = Objects.requireNonNull(agv, "agv");
        this.floor = Objects.requireNonNull(floor, "floor");
        this.objects = Objects.requireNonNull(objects, "objects");
        this.knowledge = Objects.requireNonNull(knowledge, "knowledge");
    }

    @Override
    public boolean adj(WayPoint a, WayPoint b) {
        if (floor.route(a.name(), b.name()).isEmpty()) {
            return false;
        }
        String edge = a.name() + "-" + b.name();
        return agv.state().map(s -> s.information("blockedEdge").stream()
                .noneMatch(i -> i.infoReferences().stream().anyMatch(r -> r.referenceValue().equals(edge)))).orElse(true);
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

    /** The item's weight, kg (its class attribute). */
    @Override
    public int weight(Item i) {
        return i.getWeight();
    }

    @Override
    public boolean itemAt(Item i, WayPoint w) {
        return knowledge.itemAt(i.name()).map(w.name()::equals).orElse(false);
    }

    @Override
    public WayPoint personAt(Person p) {
        return objects.waypoint(knowledge.personAt(p.name()));
    }

    @Override
    public boolean walk(Person p, WayPoint src, WayPoint dst) {
        boolean ok = agv.traverse(src.name(), dst.name(), "walk", Map.of("personId", p.name()));
        if (ok) {
            knowledge.personMoved(p.name(), dst.name());
        }
        return ok;
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
        return agv.lastFailure();
    }
}
