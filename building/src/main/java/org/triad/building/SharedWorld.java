package org.triad.building;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

import org.triad.refarc.StateSource;
import org.triad.refarc.fleet.FleetRobot;
import org.triad.runtime.app.Atom;
import org.triad.runtime.app.DomainObject;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.AppSchema;

/**
 * One building's world actor instance, shared by every robot of a fleet: the values of the world
 * actor's properties (where items lie, where people are, which waypoints are connected) as the fleet
 * last observed them. Each robot has its own robot actor instance; the state a robot plans and acts on
 * is this one world with its own robot's properties ({@link #stateFor}), so a goal that names the robot
 * actor ({@code Courier.carries(i)}) means the robot executing the task, and an item one robot picked up
 * is gone for all others.
 *
 * <p>Robots join in one of two ways: {@link #modelRobot} for robots without a platform of their own
 * (their actions do what the postconditions say, on this world), {@link #observing} for robots with one
 * (a simulator, a VDA 5050 AGV): what changed in the world while such a robot acted, as it reports the
 * world before and after, is written into this world. Thread-safe: robots act in parallel.
 */
public final class SharedWorld {
    private final AppSchema schema;
    private final Object lock = new Object();
    private final Map<String, DomainObject> objects = new LinkedHashMap<>();
    private final Map<Atom, Object> world = new LinkedHashMap<>();
    /** The robot actor's values of the situation the world started from: where model robots start. */
    private final Map<Atom, Object> robotStart = new LinkedHashMap<>();
    private long version;
    private boolean seeded;
    /** The last state a robot observing the whole building reported ({@link #follow}), null before the first. */
    private State lastFollowed;

    /**
     * A building whose world is {@code situation}'s until something starts it otherwise ({@link #startAs},
     * or the first robot with a platform, see {@link #observing}); its robot part is where {@link #modelRobot}s start.
     */
    public SharedWorld(AppSchema schema, State situation) {
        this.schema = Objects.requireNonNull(schema, "schema");
        objects.putAll(situation.objects());
        situation.values().forEach((a, v) -> (isWorld(a) ? world : robotStart).put(a, v));
    }

    public AppSchema schema() {
        return schema;
    }

    /** Whether an atom is a property of the world actor (shared) rather than of the robot actor (one per robot). */
    public boolean isWorld(Atom atom) {
        return !atom.actor().equals(schema.robot());
    }

    /** The world actor's part of the state now, with every object the building knows. */
    public State worldState() {
        synchronized (lock) {
            State.Builder b = State.builder().objects(objects.values());
            world.forEach(b::value);
            return b.build();
        }
    }

    /** How many changes the world has seen (for tests and the operator page). */
    public long version() {
        synchronized (lock) {
            return version;
        }
    }

    /**
     * The state one robot sees: this world plus that robot's own robot-actor values; objects the robot
     * reports that the building did not know yet join the building.
     */
    public State stateFor(State robotOwn) {
        synchronized (lock) {
            robotOwn.objects().forEach(objects::putIfAbsent);
            // the robot's own objects win over the building's same-named ones: a platform's generated
            // executor takes its own typed objects (a Room), not the situation's generic ones
            State.Builder b = State.builder().objects(robotOwn.objects().values()).objects(objects.values()); // the first of a name wins
            world.forEach(b::value);
            robotOwn.values().forEach((a, v) -> {
                if (!isWorld(a)) {
                    b.value(a, v);
                }
            });
            return b.build();
        }
    }

    /** Writes what changed in the world between two states one robot reported, before and after it acted. */
    public void observe(State before, State after) {
        synchronized (lock) {
            List<Atom> atoms = new ArrayList<>(before.values().keySet());
            after.values().keySet().stream().filter(a -> !before.values().containsKey(a)).forEach(atoms::add);
            after.objects().forEach(objects::putIfAbsent);
            for (Atom a : atoms) {
                if (!isWorld(a)) {
                    continue;
                }
                Object was = before.values().get(a);
                Object now = after.values().get(a);
                if (!Objects.equals(was, now)) {
                    set(a, now);
                }
            }
        }
    }

    /** Sets world atoms as one step (used by robots acting on this world); call with the lock held. */
    private void set(Atom a, Object value) {
        if (value == null || Boolean.FALSE.equals(value)) {
            world.remove(a);
        } else {
            world.put(a, value);
        }
        version++;
    }

    /** Runs {@code step} with the world held, so that a robot's look-and-act is one step for the fleet. */
    <T> T atomically(java.util.function.Function<Map<Atom, Object>, T> step) {
        synchronized (lock) {
            return step.apply(world);
        }
    }

    /** Replaces the world's values by {@code next}'s world part; call inside {@link #atomically}. */
    void replaceWorld(State next) {
        Map<Atom, Object> nextWorld = new LinkedHashMap<>();
        next.values().forEach((a, v) -> {
            if (isWorld(a)) {
                nextWorld.put(a, v);
            }
        });
        for (Atom a : new ArrayList<>(world.keySet())) {
            if (!nextWorld.containsKey(a)) {
                set(a, null);
            }
        }
        nextWorld.forEach((a, v) -> {
            if (!Objects.equals(world.get(a), v)) {
                set(a, v);
            }
        });
    }

    /** A robot of this building without a platform: its actions do what their postconditions say, on this world. */
    public ModelRobot modelRobot(String name) {
        return new ModelRobot(this, name, robotStart);
    }

    /** A model robot that starts where {@code situation} puts the robot (its robot-actor part). */
    public ModelRobot modelRobot(String name, State situation) {
        Map<Atom, Object> start = new LinkedHashMap<>();
        situation.values().forEach((a, v) -> {
            if (!isWorld(a)) {
                start.put(a, v);
            }
        });
        synchronized (lock) {
            situation.objects().forEach(objects::putIfAbsent);
        }
        return new ModelRobot(this, name, start);
    }

    /**
     * A robot with a platform of its own, as a member of this building: it reads its own robot-actor
     * values from the platform and the world from here, and what changes in the world while it acts
     * (as its platform reports it) is written here. A platform that observes the whole building
     * ({@link FleetRobot#observesBuilding()}) is followed at every report instead ({@link #follow}); the first
     * such report, taken when the first such robot joins, replaces the world (the building as it is wins over a
     * situation file).
     */
    public FleetRobot observing(FleetRobot robot) {
        if (robot instanceof BuildingMember m && m.world() == this) {
            return robot;
        }
        if (robot.observesBuilding()) {
            try {
                follow(robot.stateSource()); // its first report is the building's world
            } catch (Exception unreadable) {
                // read at its first use instead
            }
        } else {
            seedFrom(robot);
        }
        return new ObservedRobot(this, robot, robot.observesBuilding());
    }

    /**
     * The world starts as observed: the first robot with a platform that joins before the world was
     * started otherwise (see {@link #startAs}) replaces the situation's world part by what its platform
     * reports (a robot that cannot be read now leaves it as it is).
     */
    private void seedFrom(FleetRobot robot) {
        State reported;
        synchronized (lock) {
            if (seeded || version > 0) {
                return;
            }
        }
        try {
            reported = robot.stateSource().currentState();
        } catch (Exception e) {
            return;
        }
        startAs(reported);
    }

    /**
     * Starts the world as {@code situation}'s world part says, unless it was started already (by an
     * explicit situation, or by the first robot that reported its world) or has changed since: the first
     * word on the building's world wins. Returns whether this one did.
     */
    public boolean startAs(State situation) {
        synchronized (lock) {
            if (seeded || version > 0) {
                return false;
            }
            objects.putAll(situation.objects());
            replaceWorld(situation);
            seeded = true;
            version = 0;
            return true;
        }
    }

    /** A robot's own state source seen through this building. */
    StateSource view(StateSource own) {
        return () -> stateFor(own.currentState());
    }

    /**
     * Reads the state of a robot whose platform observes the whole building (every such robot of this world reports
     * the same simulation) and writes what changed in the building since the last such report into the world; the
     * first report is taken as the world. Read under the world's lock, so reports are applied in the order they were
     * taken and a late, older one cannot undo a newer one; what robots without such a platform changed in between
     * stays unless the building reports the same atoms changed. Returns the state the robot sees.
     */
    State follow(StateSource building) throws Exception {
        synchronized (lock) {
            State now = building.currentState();
            now.objects().forEach(objects::putIfAbsent);
            if (lastFollowed == null) {
                replaceWorld(now);
                seeded = true;
            } else {
                observe(lastFollowed, now);
            }
            lastFollowed = now;
            return stateFor(now);
        }
    }
}
