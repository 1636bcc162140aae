package org.triad.vda5050.master;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.function.Consumer;
import java.util.function.Function;

import org.triad.building.traffic.Decision;
import org.triad.building.traffic.Decision.Granted;
import org.triad.building.traffic.Decision.Refused;
import org.triad.building.traffic.Precedence;
import org.triad.building.traffic.ReservationTable;
import org.triad.building.traffic.ReservationTable.Changes;
import org.triad.building.traffic.Resource;
import org.triad.building.traffic.CongestionCosts;
import org.triad.building.traffic.TrafficBoard;
import org.triad.runtime.schema.ActionCosts;
import org.triad.building.traffic.TrafficMap;
import org.triad.building.traffic.Wait;

/**
 * Traffic control for the AGVs of one master: the building's {@link ReservationTable}, shared by every
 * {@link RemoteAgv#driveRoute} call, thread-safe, on the wall clock. Decisions the table makes for one robot
 * while another drives (a request granted because a corridor came free, refused because a robot was lost
 * there) wait in that robot's mailbox until its own call picks them up.
 *
 * @see RemoteAgv#driveRoute(List, TrafficControl)
 */
public final class TrafficControl {
    private final ReservationTable table;
    private final double waitBoundSeconds;
    private final Consumer<String> log;
    private final Map<String, Decision> mailbox = new HashMap<>();
    private final long origin = System.nanoTime();
    /** The doors tied to the door reservations, or null (reservations only). */
    private volatile DoorKeeper doors;
    private long requests;
    /** Whether robots make way by themselves (see {@link #stepAside(boolean)}); on unless a caller re-plans by itself. */
    private volatile boolean stepAside = true;

    /**
     * @param waitBoundSeconds how long a robot may wait for a resource before its action fails with the reason
     * @param log              where one-line reports go (waits over the bound, rogue AGVs, lost robots)
     */
    public TrafficControl(TrafficMap map, double waitBoundSeconds, Consumer<String> log) {
        if (!(waitBoundSeconds > 0) || Double.isInfinite(waitBoundSeconds)) {
            throw new IllegalArgumentException("the wait bound is a positive number of seconds, not " + waitBoundSeconds);
        }
        this.table = new ReservationTable(map, () -> (System.nanoTime() - origin) / 1e9);
        this.waitBoundSeconds = waitBoundSeconds;
        this.log = Objects.requireNonNull(log, "log");
    }

    /**
     * Ties the building's doors to the door reservations from now on: a robot granted a stretch through a kept
     * door has it opened first, and the door is asked to close once nobody holds or waits for it (see {@link DoorKeeper}).
     */
    public TrafficControl keepDoors(DoorKeeper keeper) {
        this.doors = Objects.requireNonNull(keeper, "keeper");
        return this;
    }

    /** Opens the kept doors of a granted stretch for the robot (outside the lock: it waits for the doors); the reason when one stays shut. */
    Optional<String> openDoors(String robot, List<String> stretch) {
        DoorKeeper keeper = doors;
        if (keeper == null) {
            return Optional.empty();
        }
        List<String> through = read(t -> {
            List<String> ds = new java.util.ArrayList<>();
            for (int i = 0; i + 1 < stretch.size(); i++) {
                for (Resource r : t.map().step(stretch.get(i), stretch.get(i + 1))) {
                    if (r.kind() == Resource.Kind.DOOR && !ds.contains(r.id())) {
                        ds.add(r.id());
                    }
                }
            }
            return ds;
        });
        return keeper.open(robot, through);
    }

    /**
     * Robots make way by themselves from now on (a side-node yield): one sent into a dead-end room that another robot
     * holds does not wait at the room's door, the other's only way out, but steps aside to a free neighbouring stop
     * node first and waits there for the door and the room together; one refused as a deadlock steps aside before its
     * call fails, out of the way of the robots it would have waited for, and its caller re-plans from there. On by
     * default (wherever traffic control drives: {@code ./triad serve}, the benchmarks); off for a caller that moves its
     * robots out of the way by itself (a test of the table's refusals, a dispatcher of its own), which then finds a
     * refused robot where it left it.
     */
    public TrafficControl stepAside(boolean on) {
        this.stepAside = on;
        return this;
    }

    boolean stepsAside() {
        return stepAside;
    }

    /** Robots asked to make way for a refused robot that had nowhere to go (see {@link #askToMakeWay}). */
    private final java.util.Set<String> makingWay = new java.util.HashSet<>();
    /** The cycle each robot asked to make way was asked for: it steps aside off their way (see {@link #wayOut(String, List)}). */
    private final Map<String, List<String>> makingWayFor = new HashMap<>();

    /** The robots the robot was last asked to make way for (once), or none. */
    synchronized List<String> madeWayFor(String robot) {
        List<String> c = makingWayFor.remove(robot);
        return c == null ? List.of() : c;
    }

    /**
     * A robot refused as a deadlock has no free neighbour to step aside to: the first other robot of the cycle that
     * waits and has one is asked to make way instead (its wait is withdrawn at its next state and it steps aside; see
     * {@link #makeWay}). Returns that robot, if any. Never a guide (it would leave its person behind); a robot driving to
     * charge below its reserve (urgent) only when no plain robot of the cycle can: its way forward runs through the
     * refused robot's place then, which that one cannot leave (the first 5-courier run with urgent robots never asked
     * jammed the ring at c4 for good: courier-5, charged, at c4 head to head with urgent courier-2 at c5, nowhere to go).
     */
    synchronized Optional<String> askToMakeWay(String refused, List<String> cycle) {
        for (boolean urgentToo : List.of(false, true)) {
            for (String w : cycle) {
                // nor a robot refused more often than the one with nowhere to go: that would undo rule 3's aging case
                if (!w.equals(refused) && table.robots().contains(w) && table.waiting(w).isPresent()
                        && (table.precedence(w) == Precedence.PLAIN || urgentToo && table.precedence(w) == Precedence.URGENT)
                        && (!table.robots().contains(refused) || table.refusals(w) <= table.refusals(refused)) && wayOut(w, cycle).isPresent()) {
                    makingWay.add(w);
                    makingWayFor.put(w, List.copyOf(cycle));
                    log.accept("traffic: " + w + " is asked to make way for " + refused + ", which has nowhere to step aside to"
                            + (urgentToo ? " (" + w + " drives to charge, but its way runs through there)" : ""));
                    return Optional.of(w);
                }
            }
        }
        return Optional.empty();
    }

    /** Robots whose wait at the door of a dead end the table refused, to let the robot inside out (see {@link #displaced}). */
    private final java.util.Set<String> displaced = new java.util.HashSet<>();

    /**
     * Whether the robot's last refusal was to let a robot out of the dead end at whose door it waited (once): it makes
     * way, stepping aside even if its caller drove it without (it is the only one who can move).
     */
    synchronized boolean displaced(String robot) {
        return displaced.remove(robot);
    }

    /** Whether the robot was asked to make way while it waits: its wait withdrawn (once). */
    synchronized boolean makeWay(String robot) {
        if (!makingWay.remove(robot) || table.waiting(robot).isEmpty()) {
            return false;
        }
        deliver(table.makeWay(robot)); // counted: a robot asked again and again gains precedence (rule 3's aging case)
        return true;
    }

    void note(String line) {
        log.accept(line);
    }

    /** Whether {@code node}, the route's next after {@code mouth}, is a dead end that others hold or were promised. */
    synchronized boolean deadEndTaken(String robot, String mouth, String node) {
        return table.map().hasNode(mouth) && table.map().hasNode(node) && table.deadEndTaken(mouth, node, robot);
    }

    /**
     * A stop node for one robot next to the robot's decision point that it can step aside to now (the first by name):
     * the node, the lane to it and the areas they lie in have room for it after everyone who holds or waits for them;
     * never into the lift (a step aside is a plain drive), nor into a hall for several (robots stepping aside into it
     * would all drive to its one waypoint).
     */
    synchronized Optional<String> aside(String robot) {
        return aside(robot, List.of(), false);
    }

    /**
     * {@link #aside(String)} to a place off the way the given robots wait for (see {@link #wayOut(String, List)}); with
     * {@code farther}, when no neighbour will do, a free stop node for one behind a neighbour where nobody stops (a lobby
     * spot behind the hall's centre: {@link #asideRoute}).
     */
    synchronized Optional<String> aside(String robot, List<String> outOfTheWayOf, boolean farther) {
        if (!table.robots().contains(robot) || table.isLost(robot)) {
            return Optional.empty();
        }
        String at = table.decisionPoint(robot);
        List<String> places = new java.util.ArrayList<>(placesOffTheWay(robot, at, outOfTheWayOf));
        if (farther) {
            places.addAll(placesOffTheWay(robot, at, outOfTheWayOf, placesBehindNext(at)));
        }
        for (String n : places) {
            if (newOnStep(robot, at, n).stream().allMatch(r -> r.kind() != Resource.Kind.LIFT && othersNeeding(r, robot) + 1 <= r.capacity())) {
                return Optional.of(n);
            }
        }
        return Optional.empty();
    }

    /**
     * The free stop nodes for one behind a neighbour of {@code at} that is no stop node and no lift (the lobby's spots
     * behind the hall's centre), by name. Session 14: a courier at {@code c4}, the lobby's gateway, with its neighbours on
     * the ring taken had nowhere to step aside to, and the courier on its way to charge that needed {@code c4} was asked to
     * make way instead, until its battery was empty; the lobby had free spots a hall's width away.
     */
    private List<String> placesBehindNext(String at) {
        java.util.Set<String> out = new java.util.TreeSet<>();
        for (String mid : table.map().neighbours(at)) {
            if (table.map().isStop(mid) || table.map().step(at, mid).stream().anyMatch(r -> r.kind() == Resource.Kind.LIFT)) {
                continue;
            }
            for (String n : table.map().neighbours(mid)) {
                if (!n.equals(at) && !table.map().neighbours(at).contains(n) && table.map().isStop(n) && table.map().node(n).capacity() <= 1
                        && table.needing(table.map().node(n)).isEmpty()) {
                    out.add(n);
                }
            }
        }
        return List.copyOf(out);
    }

    /** The route of a step aside from {@code at} to {@code n}: the lane between them, or through the one node between (see {@link #placesBehindNext}). */
    synchronized List<String> asideRoute(String at, String n) {
        if (table.map().edge(at, n).isPresent()) {
            return List.of(at, n);
        }
        for (String mid : new java.util.TreeSet<>(table.map().neighbours(at))) {
            if (!table.map().isStop(mid) && table.map().neighbours(mid).contains(n)) {
                return List.of(at, mid, n);
            }
        }
        throw new IllegalArgumentException("no step aside from '" + at + "' to '" + n + "'");
    }

    /**
     * Where a robot that has to get out of the others' way goes: a free neighbour ({@link #aside}) if there is one,
     * else the neighbouring stop node for one that the fewest others hold or wait for (never the lift, a taken dead end,
     * a place a lost robot blocks, nor one held by a robot that waits for this one). It may have to wait for that one
     * (an ordinary request: queued only without a cycle); before, a robot with no free neighbour stayed where it was, and
     * a robot at the door of a dead end kept the one inside shut in for good (the service's benchmark: courier-4 at
     * {@code c1}, courier-3 in the storage room).
     */
    synchronized Optional<String> wayOut(String robot) {
        return wayOut(robot, List.of());
    }

    /**
     * {@link #wayOut(String)} for a robot refused as a deadlock with the robots of its cycle: never to a place those robots
     * wait to drive through. Before, a robot refused head to head in the west corridor (at c4, the other at c1 waiting for
     * the lane c1-c4, which runs over c0) stepped aside to c0, still in the other's way, was refused there and stepped
     * back to c4, and so on: ten refusals in a row for courier-8 in one benchmark run. With no place off their way, it
     * has nowhere to go, and one of them is asked to make way ({@link #askToMakeWay}).
     */
    synchronized Optional<String> wayOut(String robot, List<String> outOfTheWayOf) {
        Optional<String> free = aside(robot, outOfTheWayOf, true);
        if (free.isPresent() || !table.robots().contains(robot) || table.isLost(robot)) {
            return free;
        }
        String at = table.decisionPoint(robot);
        Map<String, java.util.Set<String>> waitsFor = table.waitsFor();
        String best = null;
        int fewest = Integer.MAX_VALUE;
        for (String n : placesOffTheWay(robot, at, outOfTheWayOf)) {
            if (table.map().neighbours(n).equals(java.util.Set.of(at)) && !table.needing(table.map().node(n)).isEmpty()) {
                continue; // a taken dead end off here: who is in it can only come out through where this robot stands
            }
            List<Resource> step = newOnStep(robot, at, n);
            // a place held by a robot that waits for this one would be a wait in a cycle: refused, no way out; nor one held
            // by a robot it gets out of the way of: it would wait there for that one, which waits for it to leave (session 14:
            // courier-5 at c6, asked to make way for courier-3 at c7, stepped aside to c3 over the lane past c7, five
            // times in 100 s, and the robots behind both stood)
            boolean usable = step.stream().allMatch(r -> r.kind() != Resource.Kind.LIFT && table.holders(r).stream()
                    .noneMatch(h -> table.isLost(h) || outOfTheWayOf.contains(h) || waitsFor.getOrDefault(h, java.util.Set.of()).contains(robot)));
            int others = step.stream().mapToInt(r -> othersNeeding(r, robot)).sum();
            if (usable && others < fewest) {
                best = n;
                fewest = others;
            }
        }
        return Optional.ofNullable(best);
    }

    /** {@link #placesForOneNextTo} but those the robots' waiting requests need (where standing, or the lane to it, would block them). */
    private List<String> placesOffTheWay(String robot, String at, List<String> others) {
        return placesOffTheWay(robot, at, others, placesForOneNextTo(at));
    }

    /** The {@code candidates} whose step aside from {@code at} needs nothing the others' waiting requests need. */
    private List<String> placesOffTheWay(String robot, String at, List<String> others, List<String> candidates) {
        java.util.Set<Resource> way = new java.util.HashSet<>();
        for (String o : others) {
            if (!o.equals(robot) && table.robots().contains(o)) {
                way.addAll(table.wanted(o));
            }
        }
        return candidates.stream().filter(n -> table.map().standing(n).stream().noneMatch(way::contains)
                && newOnStep(robot, at, n).stream().noneMatch(way::contains)).toList();
    }

    /**
     * The stop nodes for one robot next to {@code at}: first the dead ends (rooms off {@code at}) that no waiting robot is
     * heading for, then the rest, each by name. A hall for several (the lobby) is left out: it has one waypoint, which all
     * robots getting out of the way into it would drive to. Rooms first, so that a robot getting out of the way leaves
     * the corridor: before, it took the first free neighbour by name, a corridor node ({@code c...} before {@code storage},
     * {@code ward...}), and a ring of corridor nodes for one robot each filled with robots stepping aside and waiting
     * on it, until none could move but through refusals (the dyn4j benchmark's full ground-floor ring, session 12's cause 4).
     */
    private List<String> placesForOneNextTo(String at) {
        java.util.Set<String> headedFor = new java.util.HashSet<>();
        for (String r : table.robots()) {
            headedFor.addAll(table.heading(r));
        }
        List<String> forOne = new java.util.TreeSet<>(table.map().neighbours(at)).stream()
                .filter(n -> table.map().isStop(n) && table.map().node(n).capacity() <= 1).toList();
        List<String> ordered = new java.util.ArrayList<>(forOne.stream().filter(n -> isDeadEndOff(n, at) && !headedFor.contains(n)).toList());
        forOne.stream().filter(n -> !ordered.contains(n)).forEach(ordered::add);
        return ordered;
    }

    /** Whether {@code n} is a dead end whose only way out is {@code at} (a room off a corridor node). */
    private boolean isDeadEndOff(String n, String at) {
        return table.map().neighbours(n).equals(java.util.Set.of(at));
    }

    /**
     * A free dead end next to the robot's decision point, when that is a node others drive through: where a robot whose
     * wait went over the bound clears the way while its caller re-plans (a room no robot holds, waits for or is heading
     * for, reached by a plain lane: never the lift), or none. A robot that waited in vain stood in a chain of robots each
     * waiting for the next one's node; staying there it went on blocking the ones behind it, and the benchmark's
     * standstills ended at such robots, resting on the ring after a failed drive.
     */
    synchronized Optional<String> roomAside(String robot) {
        if (!table.robots().contains(robot) || table.isLost(robot) || table.waiting(robot).isPresent()) {
            return Optional.empty();
        }
        String at = table.decisionPoint(robot);
        if (table.map().neighbours(at).size() < 2) {
            return Optional.empty(); // in a dead end already
        }
        for (String n : placesForOneNextTo(at)) {
            if (isDeadEndOff(n, at) && table.robots().stream().noneMatch(o -> table.heading(o).contains(n))
                    && newOnStep(robot, at, n).stream().allMatch(r -> r.kind() != Resource.Kind.LIFT && othersNeeding(r, robot) + 1 <= r.capacity())) {
                return Optional.of(n);
            }
        }
        return Optional.empty();
    }

    /** The resources of the step that the robot does not hold yet (a zone it stands in is no obstacle). */
    private List<Resource> newOnStep(String robot, String at, String n) {
        java.util.Set<Resource> held = table.holding(robot);
        List<String> route = asideRoute(at, n);
        java.util.Set<Resource> step = new java.util.LinkedHashSet<>();
        for (int i = 1; i < route.size(); i++) {
            step.addAll(table.map().step(route.get(i - 1), route.get(i)));
        }
        return step.stream().filter(r -> !held.contains(r)).toList();
    }

    /** How many robots other than this one hold or wait for the resource. */
    private int othersNeeding(Resource r, String robot) {
        java.util.Set<String> others = new java.util.HashSet<>(table.needing(r));
        others.remove(robot);
        return others.size();
    }

    public double waitBoundSeconds() {
        return waitBoundSeconds;
    }

    /** Reads the table under the lock (an operator page, a test, a benchmark). */
    public synchronized <T> T read(Function<ReservationTable, T> query) {
        return query.apply(table);
    }

    /** Every robot waiting for a resource, with its reason and since when: what the operator page shows. */
    public synchronized List<Wait> waits() {
        return table.waits();
    }

    /** The waits as the operator page shows them (see {@code BuildingContext.traffic()}: {@code context.traffic().add(traffic::waiting)}). */
    public synchronized List<TrafficBoard.Waiting> waiting() {
        return TrafficBoard.waiting(table);
    }

    /** Planning costs from this traffic's expected waits ({@code GoalSolver.withCosts}); see {@code CongestionCosts}. */
    public ActionCosts congestion(double secondsPerStep) {
        return CongestionCosts.of(table.map(), (a, b) -> read(t -> t.expectedWait(a, b)), secondsPerStep);
    }

    /**
     * Puts the robot on the map where it stands, unless it is there already; false when its node has no room.
     * A fleet places each robot as it joins, so that nobody is sent into the place of one that stands idle.
     */
    public synchronized boolean place(String robot, String node) {
        if (table.robots().contains(robot) && table.isLost(robot)) {
            log.accept("traffic: " + robot + " is back, at " + node + "; the place it was lost at is free again");
            deliver(table.remove(robot));
        }
        if (table.robots().contains(robot)) {
            return true;
        }
        try {
            table.place(robot, node);
            return true;
        } catch (IllegalStateException full) {
            log.accept("traffic: " + full.getMessage());
            return false;
        }
    }

    /**
     * The robot stands idle at {@code node} of its base, short of its decision point (its last drive failed and the
     * AGV stopped before it): its base ends there from now on, what lay beyond freed, so that it can start again
     * from where it stands. At its decision point, what lies behind it on its base is released (its last call may have
     * ended before the AGV reported passing it). At a node off its base, the map is out of date and is put right (see
     * {@link #resync}); a wait left over from an ended call is withdrawn. False when its node has no room for it.
     */
    synchronized boolean relocate(String robot, String node) {
        if (!table.robots().contains(robot) || table.isLost(robot)) {
            return place(robot, node);
        }
        if (table.waiting(robot).isPresent()) {
            // an idle robot starting a drive has no call waiting for it (one call at a time per robot): a wait left over
            // from an ended call would keep it off the map's place it stands at for good
            log.accept("traffic: " + robot + " starts again while a wait of an ended call was left: withdrawn");
            deliver(table.cancel(robot));
        }
        if (table.decisionPoint(robot).equals(node)) {
            // it stands at its decision point: what lies behind on its base (not reported passed, say after its last call
            // ended there) is free, or robots waiting for it would wait for a robot the wait-for graph does not see
            if (table.base(robot).size() > 1) {
                deliver(table.passed(robot, node));
            }
            return true;
        }
        if (!table.released(robot, node)) {
            return resync(robot, node);
        }
        log.accept("traffic: " + robot + " stands idle at " + node + ", short of its decision point " + table.decisionPoint(robot)
                + ": its base ends there");
        deliver(table.truncate(robot, node));
        return true;
    }

    /**
     * The AGV reports standing idle at {@code node}, which is not on its base: the map is out of date (the service's mixed
     * benchmark: courier-5 stepped aside from {@code c0} towards the pharmacy, its AGV stopped at {@code c0} and reported
     * it, the map kept it in the pharmacy, and every later drive from {@code c0} was refused, three of them in a row
     * taking the robot out of dispatch). What the AGV reports is where it stands: it is put on the map there, what it held
     * freed, when the node has room for it after everyone who holds or waits for it (rule 5, as for a robot placed anew);
     * otherwise false and it stays where the map had it.
     */
    private boolean resync(String robot, String node) {
        if (!table.map().hasNode(node)) {
            return false;
        }
        boolean room = table.map().standing(node).stream().allMatch(r -> othersNeeding(r, robot) + 1 <= r.capacity());
        if (!room) {
            log.accept("traffic: " + robot + " reports standing at " + node + ", the map has it at " + table.decisionPoint(robot)
                    + ", and " + node + " has no room for it: left where the map has it");
            return false;
        }
        log.accept("traffic: " + robot + " reports standing at " + node + ", the map had it at " + table.decisionPoint(robot)
                + " (base " + table.base(robot) + "): put where it stands, what it held freed");
        deliver(table.remove(robot));
        table.place(robot, node);
        return true;
    }

    synchronized boolean isLost(String robot) {
        return table.robots().contains(robot) && table.isLost(robot);
    }

    synchronized String decisionPoint(String robot) {
        return table.decisionPoint(robot);
    }

    synchronized Decision request(String robot, List<String> route) {
        return request(robot, route, false);
    }

    /** @param guiding whether the robot guides a person along the route: it does not make way, the others of a cycle do */
    synchronized Decision request(String robot, List<String> route, boolean guiding) {
        return request(robot, route, guiding ? Precedence.GUIDE : Precedence.PLAIN);
    }

    /** @param drive a guide or an urgent drive (to charge below its reserve) does not make way, the others of a cycle do */
    synchronized Decision request(String robot, List<String> route, Precedence drive) {
        mailbox.remove(robot);
        displaced.remove(robot); // a refusal its last call did not pick up says nothing about this one
        requests++;
        Decision d = table.request(robot, route, drive);
        for (Refused r : table.takeDisplaced()) { // robots waiting at the door of the dead end this one comes out of
            log.accept("traffic: " + r.reason());
            mailbox.put(r.robot(), r);
            displaced.add(r.robot());
        }
        return d;
    }

    /** How many stretches robots asked for so far (each a reservation granted, queued or refused): a benchmark's denominator. */
    public synchronized long requests() {
        return requests;
    }

    synchronized boolean released(String robot, String node) {
        return table.released(robot, node);
    }

    synchronized void passed(String robot, String node) {
        deliver(table.passed(robot, node));
    }

    /** As {@link #passed}, unless the node is no longer on the robot's base (it was lost or taken away meanwhile). */
    synchronized void passedIfReleased(String robot, String node) {
        if (table.robots().contains(robot) && !table.isLost(robot) && table.released(robot, node)) {
            deliver(table.passed(robot, node));
        }
    }

    /** The decision the table made for this robot since it last asked, if any. */
    synchronized Optional<Decision> take(String robot) {
        return Optional.ofNullable(mailbox.remove(robot));
    }

    /** The robot's wait, once it is longer than the bound: withdrawn, and returned with its reason. */
    synchronized Optional<Wait> overdue(String robot) {
        Optional<Wait> w = table.waiting(robot).filter(x -> table.overdue(waitBoundSeconds).contains(x));
        if (w.isPresent()) {
            deliver(table.cancel(robot));
        }
        return w;
    }

    /** The robot stops at {@code node} of its base (its order ended there): the rest is freed, its wait withdrawn. */
    synchronized void stopAt(String robot, String node) {
        if (table.robots().contains(robot) && table.released(robot, node)) {
            deliver(table.truncate(robot, node));
        }
    }

    /** The robot is down where it is (its last will, a rogue stopped, gone from the fleet): nobody is sent into its place. */
    public synchronized void lost(String robot, String why) {
        if (table.robots().contains(robot) && !table.isLost(robot)) { // once: a second call would forget the lane it stands on
            log.accept("traffic: " + robot + " lost: " + why);
            deliver(table.lost(robot, why));
        }
    }

    /** A rogue AGV stopped at {@code node}, off its base: lost where it was, and that node blocked until it is taken away. */
    synchronized void rogue(String robot, String node, String why) {
        lost(robot, why);
        if (table.map().hasNode(node)) {
            for (Resource r : table.map().standing(node)) {
                deliver(table.block(r, "robot " + robot + " stands there off its base (" + why + ")"));
            }
        }
    }

    /** The robot leaves the map (taken away): everything it held is freed, blocks it caused lifted. */
    public synchronized void remove(String robot) {
        if (table.robots().contains(robot)) {
            deliver(table.remove(robot));
        }
    }

    /** Lifts a block on the resources of this node (a rogue AGV taken away from it). */
    public synchronized void clear(String node) {
        for (Resource r : table.map().standing(node)) {
            deliver(table.unblock(r));
        }
    }

    private void deliver(Changes c) {
        DoorKeeper keeper = doors;
        if (keeper != null) { // something was released or withdrawn: a door nobody needs any more is closed
            for (String d : keeper.doors()) {
                Optional<Resource> door = table.map().area(d).filter(r -> r.kind() == Resource.Kind.DOOR);
                if (door.isPresent() && table.needing(door.get()).isEmpty()) {
                    keeper.closeIfUnneeded(d, () -> read(t -> !t.needing(door.get()).isEmpty()));
                }
            }
        }
        for (Granted g : c.granted()) {
            mailbox.put(g.robot(), g);
        }
        for (Refused r : c.refused()) {
            mailbox.put(r.robot(), r);
        }
    }
}
