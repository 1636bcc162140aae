package org.triad.examples.hospital.vda5050;

import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;

import org.triad.examples.hospital.HospitalObjects;
import org.triad.examples.hospital.LobbyParking;
import org.triad.runtime.app.FailureExplaining;
import org.triad.vda5050.master.RemoteAgv;
import org.triad.vda5050.master.TrafficControl;
import org.triad.vda5050.protocol.AgvState;

import generated.hospital.IRobot;
import generated.hospital.domain.Item;
import generated.hospital.domain.Person;
import generated.hospital.domain.WayPoint;

/**
 * The robotics expert's {@code IRobot} over VDA 5050: each action is one order (or node action) for the AGV,
 * each property is read from the AGV's last state. Why an action failed comes from the AGV's errors.
 */
public final class VdaCourier implements IRobot, FailureExplaining {
    private final RemoteAgv agv;
    private final HospitalObjects objects;
    private final HospitalKnowledge knowledge;
    /** The traffic control its drives go through (reserving lanes, doors, corridors), or null to drive each edge at once. */
    private final TrafficControl traffic;

    VdaCourier(RemoteAgv agv, HospitalObjects objects, HospitalKnowledge knowledge, TrafficControl traffic) {
        this.traffic = traffic;
        this.agv = Objects.requireNonNull(agv, "agv");
        this.objects = Objects.requireNonNull(objects, "objects");
        this.knowledge = Objects.requireNonNull(knowledge, "knowledge");
    }

    public RemoteAgv agv() {
        return agv;
    }

    /** Under traffic control a move into or out of the lobby starts or ends at a parking spot ({@link LobbyRoutes}). */
    @Override
    public boolean move(WayPoint src, WayPoint dst) {
        return traffic == null ? agv.drive(src.name(), dst.name())
                : agv.driveRoute(LobbyRoutes.of(traffic).route(agv.name(), reportedNode(), src.name(), dst.name()), traffic);
    }

    /**
     * VDA 5050's {@code startCharging} at the node: the AGV finishes it when its battery is full. Under traffic control the
     * lobby's dock is a node of its own ({@link LobbyParking#DOCK}): the courier drives there from its spot, queued for it
     * in the reservation table like for any node, charges, and parks on a free spot again, so the dock is free for the next.
     */
    @Override
    public boolean recharge(WayPoint w) {
        if (traffic == null || !w.name().equals(LobbyParking.HALL)) {
            return agv.nodeAction(w.name(), "startCharging", Map.of());
        }
        LobbyRoutes lobby = LobbyRoutes.of(traffic);
        List<String> toDock = lobby.toDock(reportedNode());
        if (!toDock.isEmpty() && !agv.driveRoute(toDock, traffic)) {
            return false;
        }
        if (!agv.nodeAction(LobbyParking.DOCK, "startCharging", Map.of())) {
            return false;
        }
        // off the dock to a free spot (if that fails, it stays on the dock, a place of its own on the map, and the next
        // courier to charge waits for it there)
        lobby.freeSpot(agv.name()).ifPresent(spot -> agv.driveRoute(List.of(LobbyParking.DOCK, LobbyParking.HALL, spot), traffic));
        return true;
    }

    /**
     * Off the ground floor's corridor onto a free parking spot in the lobby, a reserved drive, when the courier stands idle
     * on a junction of it or on the dock (the fleet calls this when its task ended, before it takes the next): a task that congestion
     * ended left its courier there, and it stood in the others' way while it rested and until its next task took it
     * on. Says where it went, or why not; empty when it stays (not on a junction, no traffic control, no free spot).
     */
    public Optional<String> parkOutOfTheWay() {
        if (traffic == null) {
            return Optional.empty();
        }
        List<String> route = LobbyRoutes.of(traffic).outOfTheWay(agv.name(), reportedNode());
        if (route.isEmpty()) {
            return Optional.empty();
        }
        return Optional.of(agv.driveRoute(route, traffic) ? "parked out of the way: " + String.join(" -> ", route)
                : "could not park out of the way (" + String.join(" -> ", route) + "): " + agv.lastFailure().orElse("?"));
    }

    /** The node the AGV last reported (a lobby's parking spot, where the models see {@code lobby}), or null. */
    private String reportedNode() {
        return agv.state().map(AgvState::lastNodeId).orElse(null);
    }

    @Override
    public boolean pick(Item i, WayPoint w) {
        boolean ok = agv.nodeAction(w.name(), "pick", Map.of("loadId", i.name()));
        if (ok) {
            knowledge.itemTaken(i.name());
        }
        return ok;
    }

    @Override
    public boolean drop(Item i, WayPoint w) {
        boolean ok = agv.nodeAction(w.name(), "drop", Map.of("loadId", i.name()));
        if (ok) {
            knowledge.itemPut(i.name(), w.name());
        }
        return ok;
    }

    @Override
    public boolean guide(Person p, WayPoint src, WayPoint dst) {
        boolean ok = traffic == null ? agv.traverse(src.name(), dst.name(), "guide", Map.of("personId", p.name()))
                : driveModelEdge(src.name(), dst.name(), new RemoteAgv.EdgeAction("guide", Map.of("personId", p.name())));
        if (ok) {
            knowledge.personMoved(p.name(), dst.name());
        }
        return ok;
    }

    @Override
    public boolean startFollowing(Person p, WayPoint w) {
        return agv.nodeAction(w.name(), "startFollowing", Map.of("personId", p.name()));
    }

    /** Where the AGV reports standing, as the models know it: {@code lobby} for a parking spot or the dock. */
    @Override
    public WayPoint loc() {
        return objects.waypoint(LobbyParking.waypointOf(state().lastNodeId()));
    }

    /** The models' edge under traffic control, {@code action} along it, the lobby's parking lanes before or after it plain. */
    private boolean driveModelEdge(String src, String dst, RemoteAgv.EdgeAction action) {
        List<String> route = LobbyRoutes.of(traffic).route(agv.name(), reportedNode(), src, dst);
        return agv.driveRoute(route, traffic, LobbyRoutes.actions(route, src, dst, action));
    }

    /** The AGV's last {@code batteryState.batteryCharge}, percent. */
    @Override
    public double battery() {
        AgvState s = state();
        if (s.batteryState() == null) {
            throw new IllegalStateException("AGV " + agv.name() + " reports no batteryState: its battery cannot be planned with");
        }
        return s.batteryState().batteryCharge();
    }

    /**
     * What a metre driven takes of the battery, percent: VDA 5050 reports the charge, not the drain, so the hospital's
     * AGVs' ({@link HospitalObjects#DRAIN_PERCENT_PER_METRE}, what the simulated AGV drains).
     */
    @Override
    public double drain() {
        return HospitalObjects.DRAIN_PERCENT_PER_METRE;
    }

    /** The charge a plan keeps in hand, percent ({@link HospitalObjects#RESERVE_PERCENT}): the AGV too drives more than the model's metres. */
    @Override
    public double reserve() {
        return HospitalObjects.RESERVE_PERCENT;
    }

    /** The factsheet's {@code maxLoadMass}, kg. */
    @Override
    public int payload() {
        return HospitalObjects.PAYLOAD_KG;
    }

    @Override
    public boolean carries(Item i) {
        return state().carries(i.name());
    }

    /** The weights of the loads the AGV reports, summed, kg (each load is an item, its {@code loadId} the item's name). */
    @Override
    public int load() {
        return state().loads() == null ? 0 : state().loads().stream().mapToInt(l -> objects.item(l.loadId()).getWeight()).sum();
    }

    @Override
    public boolean following(Person p) {
        return state().information("following").stream()
                .anyMatch(info -> info.infoReferences().stream().anyMatch(r -> r.referenceValue().equals(p.name())));
    }

    @Override
    public Optional<String> lastFailure() {
        return agv.lastFailure();
    }

    @Override
    public Optional<org.triad.runtime.app.Failure> lastFailureWithCause() {
        return agv.lastFailureWithCause(); // traffic control's congestion stays one, for the fleet service to queue the task again
    }

    private AgvState state() {
        if (agv.state().isEmpty() && !agv.awaitOnline()) {
            throw new IllegalStateException("AGV " + agv.name() + " has not reported a state on " + agv.lastFailure().orElse("the broker"));
        }
        return agv.state().orElseThrow();
    }
}
