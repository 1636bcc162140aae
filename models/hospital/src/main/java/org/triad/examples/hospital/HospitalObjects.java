package org.triad.examples.hospital;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import generated.hospital.domain.Door;
import generated.hospital.domain.Item;
import generated.hospital.domain.Lift;
import generated.hospital.domain.Person;
import generated.hospital.domain.Room;
import generated.hospital.domain.WayPoint;

/**
 * The domain objects of the simulated hospital, as in the models' Morning situation: one instance per
 * name, so that the state provider, the planner and the tasks all speak of the same objects.
 */
public final class HospitalObjects {
    /** The most a courier may carry, kg (the models' {@code Courier.payload()}, the factsheet's {@code maxLoadMass}). */
    public static final int PAYLOAD_KG = 5;
    /**
     * What a metre driven takes of a courier's battery, percent of a full one: the models' {@code Courier.drain()}
     * (the situations state it), and what the simulated couriers' batteries drain ({@link #courierBattery()}). A
     * small battery, 200 m from full to empty, so that the hospital's floor (about 40 m across) draws it down
     * visibly and a day's deliveries need the dock.
     */
    public static final double DRAIN_PERCENT_PER_METRE = 0.5;
    /**
     * The charge a plan keeps in hand, percent of a full battery: the models' {@code Courier.reserve()} (the situations
     * state it). A move is planned only when it leaves this much, because what a courier drives is not exactly the
     * models' metres (the corridors' lengths between waypoint centres): it follows people who stop and go on, steers
     * round others, drives onto the dock. A plan that ran the battery to 0 % in the models would leave nothing for
     * that; the module's README gives the measured figures.
     */
    public static final double RESERVE_PERCENT = 5.0;
    /** Traction energy per metre driven, J/m (the simulation's default). */
    private static final double JOULES_PER_METRE = 50;
    /** Charging power at the dock, W (the simulation's default): 20 s from empty to full. */
    private static final double CHARGING_WATTS = 500;

    /** A full battery of a simulated courier: {@value #JOULES_PER_METRE} J/m, so {@value #DRAIN_PERCENT_PER_METRE} % per metre. */
    public static org.triad.sim.Battery courierBattery() {
        return new org.triad.sim.Battery(JOULES_PER_METRE * 100 / DRAIN_PERCENT_PER_METRE, JOULES_PER_METRE, CHARGING_WATTS, 1);
    }

    /**
     * A simulated courier: the simulation's default robot, whose cabinet holds as many items as the payload bears
     * (every item weighs at least 1 kg), so that what it may carry is the models' rule, their weights summed.
     */
    public static org.triad.sim.RobotSpec courierSpec() {
        return org.triad.sim.RobotSpec.defaults().withCapacity(PAYLOAD_KG);
    }

    private final Map<String, WayPoint> wayPoints = new LinkedHashMap<>();
    private final Map<String, Room> rooms = new LinkedHashMap<>();
    private final Map<String, Item> items = new LinkedHashMap<>();
    private final Map<String, Person> people = new LinkedHashMap<>();
    private final Map<String, Door> doors = new LinkedHashMap<>();
    private final Map<String, Lift> lifts = new LinkedHashMap<>();

    public HospitalObjects() {
        HospitalFloor.CORRIDOR_WAYPOINTS.forEach(n -> wayPoints.put(n, new WayPoint(n)));
        room("storage", "Storage");
        room("xray", "X-ray");
        room("ward1", "Ward 1");
        room("ward2", "Ward 2");
        room("ward3", "Ward 3");
        room("lobby", "Lobby");
        room("pharmacy", "Pharmacy");
        room("ward4", "Ward 4");
        room("ward5", "Ward 5");
        item("gauze", 1);
        item("syringe", 1);
        item("bandage", 2);
        item("insulin", 1);
        person("alice", "Alice");
        person("bob", "Bob");
        HospitalFloor.CONTROLLED_DOORS.forEach(d -> doors.put(d.door(), new Door(d.door())));
        lifts.put(HospitalFloor.LIFT, new Lift(HospitalFloor.LIFT));
    }

    private void room(String id, String label) {
        Room r = new Room(id);
        r.setName(label);
        rooms.put(id, r);
    }

    private void item(String id, int weight) {
        Item i = new Item(id);
        i.setLabel(id);
        i.setWeight(weight);
        items.put(id, i);
    }

    private void person(String id, String label) {
        Person p = new Person(id);
        p.setName(label);
        people.put(id, p);
    }

    /** A corridor waypoint or a room by name. */
    public WayPoint waypoint(String name) {
        WayPoint w = rooms.containsKey(name) ? rooms.get(name) : wayPoints.get(name);
        if (w == null) {
            throw new IllegalArgumentException("the hospital has no waypoint or room '" + name + "'; it has "
                    + allWaypointNames());
        }
        return w;
    }

    public Room room(String name) {
        return require(rooms, name, "room");
    }

    public Item item(String name) {
        return require(items, name, "item");
    }

    public Person person(String name) {
        return require(people, name, "person");
    }

    public Door door(String name) {
        return require(doors, name, "door");
    }

    public Lift lift(String name) {
        return require(lifts, name, "lift");
    }

    /** The doors the building opens on request. */
    public List<Door> doors() {
        return List.copyOf(doors.values());
    }

    public List<Lift> lifts() {
        return List.copyOf(lifts.values());
    }

    /** Plain waypoints (corridors), without rooms. */
    public List<WayPoint> corridorWaypoints() {
        return List.copyOf(wayPoints.values());
    }

    public List<Room> rooms() {
        return List.copyOf(rooms.values());
    }

    public List<Item> items() {
        return List.copyOf(items.values());
    }

    public List<Person> people() {
        return List.copyOf(people.values());
    }

    private List<String> allWaypointNames() {
        List<String> all = new ArrayList<>(wayPoints.keySet());
        all.addAll(rooms.keySet());
        return all;
    }

    private static <T> T require(Map<String, T> m, String name, String kind) {
        T t = m.get(name);
        if (t == null) {
            throw new IllegalArgumentException("the hospital has no " + kind + " '" + name + "'; it has " + m.keySet());
        }
        return t;
    }
}
