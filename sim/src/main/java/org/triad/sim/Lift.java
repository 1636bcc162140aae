package org.triad.sim;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * A lift joining floors that lie side by side in the plane (they never touch, so one dyn4j world holds them all): one
 * cabin room per floor ({@link Landing}), each with a landing door. The cabin "is" at one floor at a time: its door
 * there opens, every other landing door stays closed. A ride closes the door (it waits for a clear doorway), travels
 * for {@link #secondsPerFloor()} virtual seconds per floor, then moves everyone standing in the cabin room of the
 * floor left to the same spot in the cabin room of the floor reached and opens the door there.
 *
 * <p>A lift {@link Simulation#breakLift broken} by a scripted fault stops between floors on its next (or current) ride:
 * its state is {@link Motion#FAULT} with the reason, its doors stay closed and whoever rides stays in the cabin of the
 * floor it left. Create lifts with {@link Simulation#addLift}; command them with {@link Simulation#requestLift}.
 */
public final class Lift {
    /** What the cabin does. */
    public enum Motion {
        /** Standing at {@link #currentFloor()}, its door there open (or opening). */
        STOPPED,
        /** Closing its door to leave, or travelling to {@link #destinationFloor()}. */
        MOVING,
        /** Stopped between floors; {@link #fault()} says why. */
        FAULT
    }

    /** One floor's cabin: the room the cabin is on that floor and the door between it and the floor. */
    public record Landing(int floor, String cabinRoom, String door) {
        public Landing {
            Checks.notNull("cabin room", cabinRoom);
            Checks.notNull("door", door);
        }
    }

    private final String name;
    private final List<Landing> landings;
    private final double secondsPerFloor;
    private Motion motion = Motion.STOPPED;
    private Integer currentFloor;
    private Integer destinationFloor;
    private int leftFloor;
    private double arrivesAt = Double.NaN;
    private boolean broken;
    private String fault;
    private long rides;

    Lift(String name, List<Landing> landings, double secondsPerFloor, int startFloor) {
        this.name = name;
        this.landings = List.copyOf(landings);
        this.secondsPerFloor = secondsPerFloor;
        this.currentFloor = startFloor;
        this.leftFloor = startFloor;
    }

    public String name() {
        return name;
    }

    public List<Landing> landings() {
        return Collections.unmodifiableList(landings);
    }

    /** Virtual seconds the cabin travels per floor, once its door has closed. */
    public double secondsPerFloor() {
        return secondsPerFloor;
    }

    public Motion motion() {
        return motion;
    }

    /** The floor the cabin stands at; empty while it travels or is stopped between floors. */
    public Optional<Integer> currentFloor() {
        return Optional.ofNullable(currentFloor);
    }

    /** Where the cabin goes (set while it moves, and when it stopped on the way). */
    public Optional<Integer> destinationFloor() {
        return Optional.ofNullable(destinationFloor);
    }

    /** Why the lift stopped between floors (only in {@link Motion#FAULT}). */
    public Optional<String> fault() {
        return Optional.ofNullable(fault);
    }

    /** Rides completed so far. */
    public long rides() {
        return rides;
    }

    /** The landing of {@code floor}. @throws IllegalArgumentException for a floor the lift does not serve */
    public Landing landing(int floor) {
        for (Landing l : landings) {
            if (l.floor() == floor) {
                return l;
            }
        }
        List<Integer> floors = new ArrayList<>();
        landings.forEach(l -> floors.add(l.floor()));
        throw new IllegalArgumentException("lift '" + name + "' does not serve floor " + floor + "; it serves " + floors);
    }

    /** The landing whose cabin room is {@code room}, if any. */
    public Optional<Landing> landingOfCabin(String room) {
        return landings.stream().filter(l -> l.cabinRoom().equals(room)).findFirst();
    }

    // ---- driven by the simulation, on its stepping thread ------------------------------------------------------------

    /** Returns null when accepted, else why not. */
    String request(Simulation sim, int floor) {
        landing(floor);
        if (motion == Motion.FAULT) {
            return fault;
        }
        if (motion == Motion.MOVING) {
            return Integer.valueOf(floor).equals(destinationFloor) ? null
                    : "lift '" + name + "' is on its way to floor " + destinationFloor + "; ask again when it stopped";
        }
        if (currentFloor == floor) {
            sim.openDoor(landing(floor).door());
            return null;
        }
        destinationFloor = floor;
        leftFloor = currentFloor;
        motion = Motion.MOVING;
        arrivesAt = Double.NaN;
        sim.closeDoor(landing(leftFloor).door());
        return null;
    }

    void breakDown() {
        broken = true;
    }

    void repair(Simulation sim) {
        broken = false;
        if (motion == Motion.FAULT) {
            // the service engineer brings the cabin back to the floor it left
            motion = Motion.STOPPED;
            currentFloor = leftFloor;
            destinationFloor = null;
            fault = null;
            sim.openDoor(landing(leftFloor).door());
        }
    }

    /** One step: a door that closed starts the travel; travel time up arrives (or stops between floors if broken). */
    void update(Simulation sim) {
        if (motion != Motion.MOVING) {
            return;
        }
        if (Double.isNaN(arrivesAt)) {
            if (sim.door(landing(leftFloor).door()).isOpen()) {
                return;
            }
            currentFloor = null;
            arrivesAt = sim.time() + secondsPerFloor * Math.abs(destinationFloor - leftFloor);
            if (broken) {
                motion = Motion.FAULT;
                fault = String.format(Locale.ROOT, "lift '%s' stopped between floors %d and %d", name, leftFloor, destinationFloor);
                sim.record(new TraceEvent(sim.time(), "world", fault, sim.plan().room(landing(leftFloor).cabinRoom()).bounds().center(),
                        false, "LIFT_FAULT"));
            }
            return;
        }
        if (sim.time() + 1e-9 < arrivesAt) {
            return;
        }
        Rect from = sim.plan().room(landing(leftFloor).cabinRoom()).bounds();
        Rect to = sim.plan().room(landing(destinationFloor).cabinRoom()).bounds();
        sim.carryAcross(from, to);
        currentFloor = destinationFloor;
        destinationFloor = null;
        motion = Motion.STOPPED;
        rides++;
        sim.openDoor(landing(currentFloor).door());
        sim.record(new TraceEvent(sim.time(), "world", "lift " + name + " at floor " + currentFloor, to.center(), true, ""));
    }
}
