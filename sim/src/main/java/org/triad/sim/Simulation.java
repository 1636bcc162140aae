package org.triad.sim;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.PriorityQueue;
import java.util.SplittableRandom;
import java.util.function.BooleanSupplier;

import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.ContinuousDetectionMode;
import org.dyn4j.world.World;

/**
 * A deterministic 2D simulation of a floor plan with robots, people, doors and items on dyn4j.
 * Virtual time advances in fixed steps (default 1/60 s) only when {@link #step()} is called, directly
 * or by a blocking {@link Robot} activity; there is no wall clock. For a given plan, seed and sequence of
 * calls, every run produces the same trace. Units: metres, seconds, m/s, m/s^2. Not thread-safe.
 */
public final class Simulation {
    private static final double ROBOT_DENSITY = 40;
    private static final double PERSON_DENSITY = 20;

    private final FloorPlan plan;
    private final PathPlanner planner;
    private final World<Body> world = new World<>();
    private final double dt;
    private final long seed;
    private final SplittableRandom random;
    private final boolean recordTrace;
    private final List<Robot> robots = new ArrayList<>();
    private final List<Person> people = new ArrayList<>();
    private final Map<String, Door> doors = new LinkedHashMap<>();
    private final Map<String, Lift> lifts = new LinkedHashMap<>();
    private final Map<String, Item> items = new LinkedHashMap<>();
    private final PriorityQueue<Scheduled> events = new PriorityQueue<>();
    private final Trace trace = new Trace();
    private List<Agent> agents = List.of();
    private List<Waypoint> wanderTargets;
    private long steps;
    private long eventSeq;
    private int blockings;
    private boolean stepping;
    private final List<Runnable> stepListeners = new java.util.concurrent.CopyOnWriteArrayList<>();
    private final ContactWatch contacts = new ContactWatch();
    private volatile SimulationClock clock;
    private final Map<String, Vec2> docks = new LinkedHashMap<>();
    /** Distance, metres, from a dock's position within which a robot standing still charges. */
    public static final double DOCK_RANGE = 0.5;

    private record Scheduled(double time, long seq, String label, Runnable action) implements Comparable<Scheduled> {
        @Override
        public int compareTo(Scheduled o) {
            return time != o.time ? Double.compare(time, o.time) : Long.compare(seq, o.seq);
        }
    }

    private Simulation(FloorPlan plan, long seed, double dt, boolean recordTrace) {
        this.plan = plan;
        this.planner = new PathPlanner(plan);
        this.dt = dt;
        this.seed = seed;
        this.random = new SplittableRandom(seed);
        this.recordTrace = recordTrace;
        world.setGravity(0, 0);
        world.getSettings().setStepFrequency(dt);
        world.getSettings().setAtRestDetectionEnabled(false);
        // Bodies move at most a few centimetres per step against 10 cm walls: no tunnelling, so the
        // costly time-of-impact pass is switched off.
        world.getSettings().setContinuousDetectionMode(ContinuousDetectionMode.NONE);
        for (Wall w : plan.walls()) {
            world.addBody(Bodies.wall(w.a(), w.b(), plan.wallThickness()));
        }
        for (Doorway d : plan.doorways()) {
            Body body = Bodies.wall(d.end1(), d.end2(), plan.wallThickness());
            world.addBody(body);
            doors.put(d.name(), new Door(d, body));
        }
        for (ItemPlacement i : plan.items()) {
            addItem(i.name(), i.position());
        }
    }

    /** Starts a simulation of the plan (seed 0, step 1/60 s, trace on). */
    public static Builder builder(FloorPlan plan) {
        return new Builder(Checks.notNull("floor plan", plan));
    }

    /** Configures a {@link Simulation}. */
    public static final class Builder {
        private final FloorPlan plan;
        private long seed;
        private double dt = 1.0 / 60;
        private boolean recordTrace = true;

        private Builder(FloorPlan plan) {
            this.plan = plan;
        }

        /** Seed of the random generator used by people's random choices. */
        public Builder seed(long seed) {
            this.seed = seed;
            return this;
        }

        /** Fixed step, seconds (0 &lt; step &lt;= 0.1). */
        public Builder stepSeconds(double seconds) {
            Checks.positive("step (s)", seconds);
            if (seconds > 0.1) {
                throw new IllegalArgumentException("step must be <= 0.1 s for stable physics, got " + seconds);
            }
            this.dt = seconds;
            return this;
        }

        /** Whether to record a {@link TraceFrame} per step (needed for pictures). */
        public Builder recordTrace(boolean on) {
            this.recordTrace = on;
            return this;
        }

        public Simulation build() {
            return new Simulation(plan, seed, dt, recordTrace);
        }
    }

    // ---- population ------------------------------------------------------------------------------

    /** Adds a robot at a waypoint. @throws IllegalArgumentException on unknown waypoint or duplicate name */
    public Robot addRobot(String name, String waypoint, RobotSpec spec) {
        return addRobot(name, plan.waypoint(waypoint).position(), spec);
    }

    /** Adds a robot at a position (metres). @throws IllegalArgumentException if the spot is not free */
    public Robot addRobot(String name, Vec2 position, RobotSpec spec) {
        requireNewAgentName(name);
        Checks.notNull("robot spec", spec);
        requireNoTunnelling("robot '" + name + "'", spec.maxSpeed(), spec.radius());
        requireFreeSpot("robot '" + name + "'", Checks.notNull("position", position), spec.radius());
        Robot r = new Robot(this, name, spec);
        r.body = Bodies.disc(spec.radius(), position, ROBOT_DENSITY);
        world.addBody(r.body);
        robots.add(r);
        trace.addRobot(name);
        refreshAgents();
        return r;
    }

    /** Adds a standing person at a waypoint. */
    public Person addPerson(String name, String waypoint, PersonSpec spec) {
        return addPerson(name, plan.waypoint(waypoint).position(), spec);
    }

    /** Adds a standing person at a position (metres). @throws IllegalArgumentException if the spot is not free */
    public Person addPerson(String name, Vec2 position, PersonSpec spec) {
        requireNewAgentName(name);
        Checks.notNull("person spec", spec);
        requireNoTunnelling("person '" + name + "'", spec.maxSpeed(), spec.radius());
        requireFreeSpot("person '" + name + "'", Checks.notNull("position", position), spec.radius());
        return spawnPerson(name, position, spec);
    }

    private Person spawnPerson(String name, Vec2 position, PersonSpec spec) {
        Person p = new Person(this, name, spec);
        p.body = Bodies.disc(spec.radius(), position, PERSON_DENSITY);
        world.addBody(p.body);
        people.add(p);
        trace.addPerson(name);
        refreshAgents();
        return p;
    }

    /**
     * Adds a charging dock at a position (metres): a robot standing still within {@value #DOCK_RANGE} m of it
     * charges its {@link Battery}.
     *
     * @throws IllegalArgumentException for a duplicate name or a position outside every room
     */
    public void addDock(String name, Vec2 position) {
        Checks.name("dock name", name);
        Checks.notNull("position", position);
        if (docks.containsKey(name)) {
            throw new IllegalArgumentException("duplicate dock '" + name + "'");
        }
        if (plan.roomAt(position).isEmpty()) {
            throw new IllegalArgumentException("dock '" + name + "' at " + position + " is outside every room");
        }
        docks.put(name, position);
    }

    /** Docks by name, in the order added. */
    public Map<String, Vec2> docks() {
        return Collections.unmodifiableMap(docks);
    }

    boolean atDock(Vec2 p) {
        for (Vec2 d : docks.values()) {
            if (d.distance(p) <= DOCK_RANGE) {
                return true;
            }
        }
        return false;
    }

    /** Adds an item at a position (metres) inside a room. */
    public Item addItem(String name, Vec2 position) {
        Checks.name("item name", name);
        Checks.notNull("position", position);
        if (items.containsKey(name)) {
            throw new IllegalArgumentException("duplicate item '" + name + "'");
        }
        if (plan.roomAt(position).isEmpty()) {
            throw new IllegalArgumentException("item '" + name + "' at " + position + " is outside every room");
        }
        Item i = new Item(this, name, position);
        items.put(name, i);
        trace.addItem(name);
        return i;
    }

    private void requireNewAgentName(String name) {
        Checks.name("name", name);
        for (Robot r : robots) {
            if (r.name.equals(name)) {
                throw new IllegalArgumentException("duplicate robot or person name '" + name + "'");
            }
        }
        for (Person p : people) {
            if (p.name.equals(name)) {
                throw new IllegalArgumentException("duplicate robot or person name '" + name + "'");
            }
        }
    }

    /** Continuous collision detection is off, so a disc must not move more than half its radius per step. */
    private void requireNoTunnelling(String what, double maxSpeed, double radius) {
        if (maxSpeed * dt > 0.5 * radius) {
            throw new IllegalArgumentException(String.format(Locale.ROOT,
                    "%s: %.2f m/s moves %.3f m per %.4f s step, more than half its radius %.2f m; use a smaller step",
                    what, maxSpeed, maxSpeed * dt, dt, radius));
        }
    }

    private void requireFreeSpot(String what, Vec2 p, double radius) {
        if (!isFree(p, radius)) {
            throw new IllegalArgumentException(what + " at " + p + " would overlap a wall or lie outside every room");
        }
        for (Agent a : agents) {
            if (a.position().distance(p) < a.radius + radius) {
                throw new IllegalArgumentException(what + " at " + p + " would overlap '" + a.name + "'");
            }
        }
    }

    private void refreshAgents() {
        List<Agent> list = new ArrayList<>(robots);
        for (Person p : people) {
            if (p.isPresent()) {
                list.add(p);
            }
        }
        agents = Collections.unmodifiableList(list);
    }

    // ---- lookup ----------------------------------------------------------------------------------

    public FloorPlan plan() {
        return plan;
    }

    public Trace trace() {
        return trace;
    }

    public long seed() {
        return seed;
    }

    /** Fixed step, seconds. */
    public double stepSeconds() {
        return dt;
    }

    /** Virtual time since start, seconds. */
    public double time() {
        return steps * dt;
    }

    /** Number of steps taken. */
    public long steps() {
        return steps;
    }

    /** @throws IllegalArgumentException for an unknown name */
    public Robot robot(String name) {
        for (Robot r : robots) {
            if (r.name.equals(name)) {
                return r;
            }
        }
        throw new IllegalArgumentException("unknown robot '" + name + "'");
    }

    /** @throws IllegalArgumentException for an unknown name */
    public Person person(String name) {
        for (Person p : people) {
            if (p.name.equals(name)) {
                return p;
            }
        }
        throw new IllegalArgumentException("unknown person '" + name + "'");
    }

    /** @throws IllegalArgumentException for an unknown name */
    public Item item(String name) {
        Item i = name == null ? null : items.get(name);
        if (i == null) {
            throw new IllegalArgumentException("unknown item '" + name + "'; known: " + items.keySet());
        }
        return i;
    }

    /** @throws IllegalArgumentException for an unknown name */
    public Door door(String name) {
        Door d = name == null ? null : doors.get(name);
        if (d == null) {
            throw new IllegalArgumentException("unknown door '" + name + "'; known: " + doors.keySet());
        }
        return d;
    }

    public List<Robot> robots() {
        return Collections.unmodifiableList(robots);
    }

    /** People currently present, in the order added. */
    public List<Person> people() {
        List<Person> out = new ArrayList<>();
        people.stream().filter(Person::isPresent).forEach(out::add);
        return out;
    }

    public List<Item> items() {
        return List.copyOf(items.values());
    }

    /**
     * Items lying in the room (not carried, not removed), in the order added.
     *
     * @throws IllegalArgumentException for an unknown room
     */
    public List<Item> itemsIn(String room) {
        Room r = plan.room(room);
        List<Item> out = new ArrayList<>();
        for (Item i : items.values()) {
            if (!i.isRemoved() && i.holder().isEmpty() && i.room().map(x -> x.equals(r)).orElse(false)) {
                out.add(i);
            }
        }
        return out;
    }

    public List<Door> doors() {
        return List.copyOf(doors.values());
    }

    // ---- world changes ---------------------------------------------------------------------------

    public void openDoor(String name) {
        Door d = door(name);
        if (!d.isOpen()) {
            record(new TraceEvent(time(), "world", "door " + name + " opened", d.doorway().center(), true, ""));
        }
        d.open();
    }

    /** Requests the door to close; it closes as soon as nobody stands in the doorway. */
    public void closeDoor(String name) {
        Door d = door(name);
        d.requestClose();
        updateDoor(d);
    }

    private void updateDoor(Door d) {
        if (d.update(agents, plan.wallThickness())) {
            record(new TraceEvent(time(), "world", "door " + d.name() + " closed", d.doorway().center(), true, ""));
        }
    }

    /**
     * Adds a lift whose cabin rooms and landing doors are in the floor plan; it starts standing at {@code startFloor}
     * with that landing's door open and every other landing door closed.
     *
     * @param secondsPerFloor virtual seconds of travel per floor (&gt; 0), after the door has closed
     * @throws IllegalArgumentException for a duplicate name, fewer than two landings, two landings of one floor, an
     *                                  unknown cabin room or door, or a start floor the lift does not serve
     */
    public Lift addLift(String name, List<Lift.Landing> landings, double secondsPerFloor, int startFloor) {
        Checks.notNull("lift name", name);
        Checks.notNull("landings", landings);
        Checks.positive("seconds per floor", secondsPerFloor);
        if (lifts.containsKey(name)) {
            throw new IllegalArgumentException("duplicate lift '" + name + "'");
        }
        if (landings.size() < 2) {
            throw new IllegalArgumentException("lift '" + name + "' needs at least two landings, not " + landings.size());
        }
        java.util.Set<Integer> floors = new java.util.HashSet<>();
        for (Lift.Landing l : landings) {
            if (!floors.add(l.floor())) {
                throw new IllegalArgumentException("lift '" + name + "' has two landings on floor " + l.floor());
            }
            plan.room(l.cabinRoom());
            door(l.door());
        }
        Lift lift = new Lift(name, landings, secondsPerFloor, startFloor);
        lift.landing(startFloor);
        for (Lift.Landing l : landings) {
            if (l.floor() == startFloor) {
                openDoor(l.door());
            } else {
                closeDoor(l.door());
            }
        }
        lifts.put(name, lift);
        return lift;
    }

    /** @throws IllegalArgumentException for an unknown name */
    public Lift lift(String name) {
        Lift l = name == null ? null : lifts.get(name);
        if (l == null) {
            throw new IllegalArgumentException("unknown lift '" + name + "'; known: " + lifts.keySet());
        }
        return l;
    }

    public List<Lift> lifts() {
        return List.copyOf(lifts.values());
    }

    /**
     * Calls the lift to {@code floor}: at that floor already, its door opens; else it closes its door, travels and
     * opens at {@code floor} (see {@link Lift}).
     *
     * @return empty when accepted, else why the lift refuses (stopped between floors, on its way elsewhere)
     * @throws IllegalArgumentException for an unknown lift or a floor it does not serve
     */
    public java.util.Optional<String> requestLift(String name, int floor) {
        return java.util.Optional.ofNullable(lift(name).request(this, floor));
    }

    /** A fault: the lift stops between floors on its current or next ride, until {@link #repairLift}. */
    public void breakLift(String name) {
        lift(name).breakDown();
    }

    /** Ends a fault: a cabin stopped between floors returns to the floor it left and opens there. */
    public void repairLift(String name) {
        lift(name).repair(this);
    }

    /** Moves every agent standing in {@code from} to the same spot of {@code to} (a lift's ride), at rest. */
    void carryAcross(Rect from, Rect to) {
        double dx = to.minX() - from.minX();
        double dy = to.minY() - from.minY();
        for (Agent a : agents) {
            if (from.contains(a.position())) {
                a.body.translate(dx, dy);
                a.body.setLinearVelocity(0, 0);
                if (a instanceof Robot r) {
                    r.carried(dx, dy);
                }
            }
        }
    }

    public void lockDoor(String name, boolean locked) {
        door(name).setLocked(locked);
    }

    public void removeItem(String name) {
        Item i = item(name);
        record(new TraceEvent(time(), "world", "item " + name + " removed", i.position(), true, ""));
        i.remove();
    }

    /** Removes a person from the world. */
    public void removePerson(String name) {
        Person p = person(name);
        if (p.isPresent()) {
            p.leave();
            world.removeBody(p.body);
            refreshAgents();
        }
    }

    /** Events at virtual time {@code t} seconds (not in the past). */
    public EventScript at(double t) {
        Checks.finite("event time (s)", t);
        if (t < time() - 1e-9) {
            throw new IllegalArgumentException("event time " + t + " s is in the past (now " + time() + " s)");
        }
        return new EventScript(this, t);
    }

    void schedule(double t, String label, Runnable action) {
        events.add(new Scheduled(t, eventSeq++, label, action));
    }

    void blockSegment(Vec2 a, Vec2 b, int count, double until, String label) {
        Vec2 mid = a.plus(b).times(0.5);
        Vec2 n = b.minus(a).normalized().perpendicular();
        Rect r = plan.roomAt(mid).orElseThrow().bounds();
        double plus = exit(mid, n, r);
        double minus = exit(mid, n.times(-1), r);
        double spacing = (plus + minus) / count;
        int id = ++blockings;
        List<String> names = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            String name = "blocker" + id + "." + (i + 1);
            spawnPerson(name, mid.plus(n.times(-minus + spacing * (i + 0.5))), PersonSpec.defaults())
                    .setYieldsToRobots(false);
            names.add(name);
        }
        record(new TraceEvent(time(), "world", "block " + label, mid, true, names.toString()));
        schedule(until, "unblock " + label, () -> {
            names.forEach(this::removePerson);
            record(new TraceEvent(time(), "world", "unblock " + label, mid, true, ""));
        });
    }

    /** Distance from p along unit direction d to the border of r. */
    private static double exit(Vec2 p, Vec2 d, Rect r) {
        double t = Double.POSITIVE_INFINITY;
        if (d.x() > 1e-9) {
            t = Math.min(t, (r.maxX() - p.x()) / d.x());
        } else if (d.x() < -1e-9) {
            t = Math.min(t, (r.minX() - p.x()) / d.x());
        }
        if (d.y() > 1e-9) {
            t = Math.min(t, (r.maxY() - p.y()) / d.y());
        } else if (d.y() < -1e-9) {
            t = Math.min(t, (r.minY() - p.y()) / d.y());
        }
        return t;
    }

    // ---- time ------------------------------------------------------------------------------------

    /**
     * Advances virtual time by one step: due events, doors, agent controllers, physics, contacts, trace.
     *
     * @throws IllegalStateException when a {@link SimulationClock} steps this simulation and the caller is not it
     */
    public void step() {
        SimulationClock owner = clock;
        if (owner != null && !owner.isClockThread()) {
            throw new IllegalStateException("this simulation is stepped by its clock; command it through SimulationClock.call/submit");
        }
        requireNotStepping();
        stepping = true;
        try {
            double now = time();
            while (!events.isEmpty() && events.peek().time() <= now + 1e-9) {
                events.poll().action().run();
            }
            for (Door d : doors.values()) {
                updateDoor(d);
            }
            for (Lift l : lifts.values()) {
                l.update(this);
            }
            for (Agent a : agents) {
                a.control(dt);
            }
            world.step(1);
            steps++;
            for (Agent a : agents) {
                a.afterStep();
            }
            for (Contact c : contacts.check(robots, time())) {
                record(new TraceEvent(c.time(), "world", "contact " + c.first() + " " + c.second(), c.position(), true, ""));
            }
            if (recordTrace) {
                recordFrame();
            }
        } finally {
            stepping = false;
        }
        for (Runnable l : stepListeners) {
            l.run();
        }
    }

    /**
     * Runs {@code listener} after every step, on the thread that steps: the place to read a consistent
     * picture of the world (this class is not thread-safe) or to pace virtual time against the wall clock.
     * The listener may read the simulation but must not step it.
     */
    public void addStepListener(Runnable listener) {
        stepListeners.add(Checks.notNull("listener", listener));
    }

    /**
     * Calls {@code listener} on the stepping thread whenever two robots come into contact (their discs touch, within
     * {@value ContactWatch#TOUCH} m); a pair is reported again only after it has been apart by
     * {@value ContactWatch#APART} m. The listener may read the simulation but must not step it.
     */
    public void onContact(java.util.function.Consumer<Contact> listener) {
        contacts.listen(Checks.notNull("listener", listener));
    }

    /** Robot-robot contacts so far, in order. */
    public List<Contact> contacts() {
        return contacts.all();
    }

    /** The clock that steps this simulation, if one was started ({@link SimulationClock#start}). */
    public java.util.Optional<SimulationClock> clock() {
        return java.util.Optional.ofNullable(clock);
    }

    void attach(SimulationClock c) {
        if (clock != null) {
            throw new IllegalStateException("this simulation already has a clock");
        }
        clock = c;
    }

    /**
     * Runs {@code body} under the clock's lock if a clock steps this simulation and the caller is another thread, else
     * directly (the clock's own thread holds the lock already; a blocking activity there fails in its await).
     */
    <T> T locked(java.util.function.Supplier<T> body) {
        SimulationClock c = clock;
        return c == null || c.isClockThread() ? body.get() : c.call(s -> body.get());
    }

    /** Advances virtual time by {@code seconds} (rounded up to whole steps). */
    public void runFor(double seconds) {
        Checks.nonNegative("duration (s)", seconds);
        long n = (long) Math.ceil(seconds / dt - 1e-9);
        for (long i = 0; i < n; i++) {
            step();
        }
    }

    /** Steps until the condition holds or {@code timeoutSeconds} pass; returns whether it holds. */
    public boolean runUntil(BooleanSupplier condition, double timeoutSeconds) {
        Checks.notNull("condition", condition);
        Checks.nonNegative("timeout (s)", timeoutSeconds);
        double end = time() + timeoutSeconds;
        while (!condition.getAsBoolean()) {
            if (time() >= end - 1e-9) {
                return false;
            }
            step();
        }
        return true;
    }

    // ---- internals -------------------------------------------------------------------------------

    void requireNotStepping() {
        if (stepping) {
            throw new IllegalStateException("blocking simulation calls are not allowed inside a step (e.g. from events)");
        }
    }

    /** Waypoints that are not in a doorway, where wandering people may pause. */
    List<Waypoint> wanderTargets() {
        if (wanderTargets == null) {
            List<Waypoint> list = new ArrayList<>();
            for (Waypoint w : plan.waypoints()) {
                boolean inDoorway = false;
                for (Doorway d : plan.doorways()) {
                    inDoorway |= Segments.pointDistance(w.position(), d.end1(), d.end2()) < 0.5;
                }
                if (!inDoorway) {
                    list.add(w);
                }
            }
            wanderTargets = list.isEmpty() ? plan.waypoints() : List.copyOf(list);
        }
        return wanderTargets;
    }

    List<Agent> agents() {
        return agents;
    }

    PathPlanner planner() {
        return planner;
    }

    SplittableRandom random() {
        return random;
    }

    void record(TraceEvent e) {
        trace.add(e);
    }

    boolean isFree(Vec2 p, double radius) {
        if (plan.roomAt(p).isEmpty() || !plan.clearOfWalls(p, radius)) {
            return false;
        }
        for (Door d : doors.values()) {
            if (!d.isOpen() && Segments.pointDistance(p, d.doorway().end1(), d.doorway().end2())
                    < radius + plan.wallThickness() / 2) {
                return false;
            }
        }
        return true;
    }

    String peopleNear(Vec2 p, double range) {
        List<String> names = new ArrayList<>();
        for (Agent a : agents) {
            if (a.position().distance(p) - a.radius <= range && a.position().distance(p) > 1e-9) {
                names.add(a.name);
            }
        }
        return names.isEmpty() ? "nobody (static obstacle)" : names.toString();
    }

    private void recordFrame() {
        int nr = robots.size();
        double[] rx = new double[nr];
        double[] ry = new double[nr];
        double[] rh = new double[nr];
        double[] rb = new double[nr];
        for (int i = 0; i < nr; i++) {
            Vec2 p = robots.get(i).position();
            rx[i] = p.x();
            ry[i] = p.y();
            rh[i] = robots.get(i).heading();
            rb[i] = robots.get(i).battery().percent();
        }
        int np = people.size();
        double[] px = new double[np];
        double[] py = new double[np];
        for (int i = 0; i < np; i++) {
            Person p = people.get(i);
            Vec2 pos = p.isPresent() ? p.position() : null;
            px[i] = pos == null ? Double.NaN : pos.x();
            py[i] = pos == null ? Double.NaN : pos.y();
        }
        double[] ix = new double[items.size()];
        double[] iy = new double[items.size()];
        int k = 0;
        for (Item it : items.values()) {
            Vec2 pos = it.isRemoved() ? null : it.position();
            ix[k] = pos == null ? Double.NaN : pos.x();
            iy[k] = pos == null ? Double.NaN : pos.y();
            k++;
        }
        boolean[] open = new boolean[doors.size()];
        k = 0;
        for (Door d : doors.values()) {
            open[k++] = d.isOpen();
        }
        trace.add(new TraceFrame(time(), rx, ry, rh, px, py, ix, iy, open, rb));
    }

    @Override
    public String toString() {
        return String.format(Locale.ROOT, "Simulation[t=%.2fs, %d robots, %d people, %d items]", time(), robots.size(),
                people().size(), items.size());
    }
}
