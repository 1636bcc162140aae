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
 * opened at a floor holds its door open {@value #HOLD_SECONDS} simulated seconds before it serves the next request, so
 * that the robot it came for can drive in before a robot queued elsewhere calls it away. The lift's state is published (retained) when a request is served and whenever the cabin's motion, floor or
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
        if (elsewhere || !waiting.get(name).isEmpty() || leavesSomeoneBehind(s, l, r)) {
            waiting.get(name).add(new Waiting(r, s.time()));
            return;
        }
        serve(s, l, r);
    }

    private void serve(Simulation s, Lift l, LiftRequest r) {
        lastRequest.put(l.name(), r.requestId());
        Optional<String> refused = s.requestLift(l.name(), r.destinationFloor());
        publish(s, l, refused.orElse(null));
    }

    /** Runs on the clock thread after every step: serves a waiting request once the cabin stopped; publishes changes. */
    private void step(Simulation s) {
        for (Lift l : s.lifts()) {
            Deque<Waiting> q = waiting.get(l.name());
            while (q != null && !q.isEmpty() && l.motion() != Lift.Motion.MOVING && s.time() - openedAt.getOrDefault(l.name(), -HOLD_SECONDS) >= HOLD_SECONDS
                    && (!leavesSomeoneBehind(s, l, q.peek().request()) || s.time() - q.peek().since() >= DWELL_SECONDS)) {
                serve(s, l, q.poll().request());
            }
            LiftState now = state(s, l, published.containsKey(l.name()) ? published.get(l.name()).reason() : null);
            LiftState last = published.get(l.name());
            if (last == null || !Objects.equals(now.motionState(), last.motionState()) || !Objects.equals(now.currentFloor(), last.currentFloor())
                    || !Objects.equals(now.doorMode(), last.doorMode())) {
                if (DeviceMessages.STOPPED.equals(now.motionState()) && DeviceMessages.OPEN.equals(now.doorMode())) {
                    openedAt.put(l.name(), s.time());
                }
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
