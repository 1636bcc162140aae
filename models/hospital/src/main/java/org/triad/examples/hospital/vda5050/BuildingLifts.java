package org.triad.examples.hospital.vda5050;

import java.time.Instant;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;

import org.triad.examples.hospital.HospitalBuilding;
import org.triad.sim.Lift;
import org.triad.sim.Simulation;
import org.triad.sim.SimulationClock;
import org.triad.vda5050.devices.DeviceLink;
import org.triad.vda5050.devices.DeviceMessages;
import org.triad.vda5050.devices.DeviceMessages.LiftRequest;
import org.triad.vda5050.devices.DeviceMessages.LiftState;

/**
 * The building's lifts as devices on the broker ({@link DeviceMessages}): a request for a floor is executed on the
 * building's clock (the cabin closes its door, travels and opens at the floor; at the floor already, it opens there).
 * A request that comes while the cabin travels elsewhere waits for it to stop, then is served (in the order they
 * came); so does a request to leave while another robot stands in the cabin (it does not carry off a robot that did
 * not ask, unless that robot stays longer than {@value #DWELL_SECONDS} simulated seconds), and a cabin that has just
 * serving a request is kept for it until it stood open at the request's floor {@value #HOLD_SECONDS} simulated seconds
 * (requests that come meanwhile wait), so that the robot it came for sees it open and can drive in before a robot
 * queued elsewhere calls it away. The lift's state is published (retained) when a request is served and whenever the cabin's motion, floor or
 * door changes, naming the request it last acted on; a lift stopped between floors reports FAULT with the reason, and
 * every request that comes then is answered FAULT with it.
 */
public final class BuildingLifts {
    /** Simulated seconds a waiting request gives a robot standing in the cabin to leave it. */
    static final double DWELL_SECONDS = 30;
    /** Simulated seconds a cabin that opened at a floor waits before it serves a queued request: time for its robot to enter. */
    static final double HOLD_SECONDS = 10;

    private record Waiting(LiftRequest request, double since) {
    }

    private final DeviceLink link;
    private final Map<String, String> lastRequest = new LinkedHashMap<>();
    private final Map<String, LiftState> published = new LinkedHashMap<>();
    private final Map<String, Deque<Waiting>> waiting = new LinkedHashMap<>();
    /** When each lift's cabin last stood open at a floor (simulated seconds). */
    private final Map<String, Double> openedAt = new LinkedHashMap<>();
    /**
     * The lifts serving a request whose cabin has not yet stood open at its floor: nothing else is served meanwhile, or
     * a request that comes while the cabin arrives (or while its door opens) would call it away before its robot saw it
     * open. Since when (simulated seconds); a cabin that does not stand open within {@value #DWELL_SECONDS} s is not
     * kept longer (its door may be held by something in its way).
     */
    private final Map<String, Double> arriving = new LinkedHashMap<>();

    private BuildingLifts(DeviceLink link) {
        this.link = link;
    }

    /** Serves every lift of the running building on {@code link}. */
    public static BuildingLifts serve(HospitalBuilding building, DeviceLink link) {
        Objects.requireNonNull(link, "link");
        SimulationClock clock = building.clock().orElseThrow(() -> new IllegalStateException("start the building's clock first"));
        BuildingLifts lifts = new BuildingLifts(link);
        clock.run(s -> {
            for (Lift l : s.lifts()) {
                lifts.waiting.put(l.name(), new ArrayDeque<>());
                lifts.publish(s, l, null);
            }
            s.addStepListener(() -> lifts.step(s));
        });
        for (String name : clock.call(s -> s.lifts().stream().map(Lift::name).toList())) {
            link.subscribe(DeviceMessages.liftRequestTopic(name), LiftRequest.class, r -> clock.submit(s -> lifts.handle(s, name, r)));
        }
        return lifts;
    }

    /** The lifts' names, for the building's start-up line. */
    public static List<String> names(SimulationClock clock) {
        return clock.call(s -> s.lifts().stream().map(Lift::name).toList());
    }

    /** Runs on the clock thread. */
    private void handle(Simulation s, String name, LiftRequest r) {
        Lift l = s.lift(name);
        if (l.landings().stream().noneMatch(x -> x.floor() == r.destinationFloor())) {
            lastRequest.put(name, r.requestId());
            publish(s, l, "lift '" + name + "' does not serve floor " + r.destinationFloor() + "; it serves "
                    + l.landings().stream().map(Lift.Landing::floor).toList());
            return;
        }
        boolean elsewhere = l.motion() == Lift.Motion.MOVING && !Integer.valueOf(r.destinationFloor()).equals(l.destinationFloor().orElse(null));
        if (elsewhere || !waiting.get(name).isEmpty() || held(s, l) || leavesSomeoneBehind(s, l, r)) {
            waiting.get(name).add(new Waiting(r, s.time()));
            return;
        }
        serve(s, l, r);
    }

    private void serve(Simulation s, Lift l, LiftRequest r) {
        lastRequest.put(l.name(), r.requestId());
        Optional<String> refused = s.requestLift(l.name(), r.destinationFloor());
        if (refused.isEmpty()) {
            arriving.put(l.name(), s.time());
            openedIfSo(s, l);
        }
        publish(s, l, refused.orElse(null));
    }

    /** Whether the cabin is kept for the request it serves: not yet open at its floor, or open there for less than the hold. */
    private boolean held(Simulation s, Lift l) {
        return l.motion() == Lift.Motion.STOPPED
                && (s.time() - arriving.getOrDefault(l.name(), -DWELL_SECONDS) < DWELL_SECONDS || s.time() - openedAt.getOrDefault(l.name(), -HOLD_SECONDS) < HOLD_SECONDS);
    }

    /** Notes the cabin standing open at a floor: the hold for its robot starts now. */
    private void openedIfSo(Simulation s, Lift l) {
        LiftState now = state(s, l, null);
        if (DeviceMessages.STOPPED.equals(now.motionState()) && DeviceMessages.OPEN.equals(now.doorMode()) && arriving.remove(l.name()) != null) {
            openedAt.put(l.name(), s.time());
        }
    }

    /** Runs on the clock thread after every step: serves a waiting request once the cabin stopped; publishes changes. */
    private void step(Simulation s) {
        for (Lift l : s.lifts()) {
            Deque<Waiting> q = waiting.get(l.name());
            openedIfSo(s, l);
            if (l.motion() == Lift.Motion.FAULT) {
                arriving.remove(l.name());
            } else if (l.motion() == Lift.Motion.MOVING && arriving.containsKey(l.name())) {
                arriving.put(l.name(), s.time()); // the wait for the door counts from the arrival, however long the ride
            }
            while (q != null && !q.isEmpty() && l.motion() != Lift.Motion.MOVING && !held(s, l)
                    && (!leavesSomeoneBehind(s, l, q.peek().request()) || s.time() - q.peek().since() >= DWELL_SECONDS)) {
                serve(s, l, q.poll().request());
            }
            LiftState now = state(s, l, published.containsKey(l.name()) ? published.get(l.name()).reason() : null);
            LiftState last = published.get(l.name());
            if (last == null || !Objects.equals(now.motionState(), last.motionState()) || !Objects.equals(now.currentFloor(), last.currentFloor())
                    || !Objects.equals(now.doorMode(), last.doorMode())) {
                publish(s, l, null);
            }
        }
    }

    /** Whether serving {@code r} would carry off (or shut in) a robot other than the requester standing in the cabin. */
    private static boolean leavesSomeoneBehind(Simulation s, Lift l, LiftRequest r) {
        if (l.motion() != Lift.Motion.STOPPED || l.currentFloor().isEmpty() || l.currentFloor().get() == r.destinationFloor()) {
            return false;
        }
        org.triad.sim.Rect cabin = s.plan().room(l.landing(l.currentFloor().get()).cabinRoom()).bounds();
        return s.robots().stream().anyMatch(x -> !x.name().equals(r.requester()) && cabin.contains(x.position()));
    }

    private LiftState state(Simulation s, Lift l, String reason) {
        String motion = switch (l.motion()) {
            case STOPPED -> DeviceMessages.STOPPED;
            case MOVING -> DeviceMessages.MOVING;
            case FAULT -> DeviceMessages.FAULT;
        };
        String door = l.currentFloor().map(f -> {
            org.triad.sim.Door d = s.door(l.landing(f).door());
            return d.isOpen() ? (d.isClosing() ? DeviceMessages.MOVING : DeviceMessages.OPEN) : DeviceMessages.CLOSED;
        }).orElse(DeviceMessages.CLOSED);
        String why = l.motion() == Lift.Motion.FAULT ? l.fault().orElse("out of order") : reason;
        return new LiftState(l.name(), l.currentFloor().orElse(null), l.destinationFloor().orElse(null), motion, door,
                lastRequest.get(l.name()), why, Instant.now().toString());
    }

    private void publish(Simulation s, Lift l, String reason) {
        LiftState st = state(s, l, reason);
        published.put(l.name(), st);
        link.publish(DeviceMessages.liftStateTopic(l.name()), st, true);
    }
}
