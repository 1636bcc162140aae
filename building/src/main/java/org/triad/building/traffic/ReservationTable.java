package org.triad.building.traffic;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.function.DoubleSupplier;

import org.triad.building.traffic.Decision.Granted;
import org.triad.building.traffic.Decision.Refused;
import org.triad.building.traffic.Decision.Waiting;

/**
 * Who holds which resource of a {@link TrafficMap}, who waits for which, and the rule that keeps the
 * waiting free of cycles (the module's README states it and argues why it cannot deadlock).
 *
 * <p>A robot holds what it stands on ({@link TrafficMap#standing}) and its <em>base</em>: the route it is
 * allowed to drive, from the node it last passed to its <em>decision point</em>. It asks for its route one
 * <em>stretch</em> at a time: from its decision point to the next stop node (or the route's end; through a
 * hall for several robots that it would fill, to the stop node after it; into a dead-end room that is taken,
 * instead of waiting at its door), all resources of the stretch at
 * once or none. A request is granted when every resource it needs has room for it after the robots queued
 * earlier for that resource; otherwise it queues in arrival order, unless queuing would close a cycle of
 * robots waiting for each other: then it is put ahead of the robots that wait for it, if that keeps the
 * waits free of cycles, or else refused with the reason, and the robot's action fails (RefArc re-plans).
 * A request for a resource blocked by a lost robot or an obstacle is refused with the reason.
 *
 * <p>Not thread-safe: one owner (master control's traffic thread) calls it, or callers synchronize.
 * Times are seconds on the given clock (simulated or wall-clock).
 */
public final class ReservationTable {
    private final TrafficMap map;
    private final DoubleSupplier clock;
    private final Map<String, RobotState> robots = new LinkedHashMap<>();
    private final Map<Resource, Set<String>> holders = new HashMap<>();
    /** Requests waiting, in arrival order. */
    private final TreeMap<Long, Request> queue = new TreeMap<>();
    private final Map<Resource, String> blocked = new HashMap<>();
    private final TrafficStats stats;
    /** Waiting requests refused to let another robot out of a dead end (see {@link #evictFromTheDoor}), not yet taken. */
    private final List<Refused> displaced = new ArrayList<>();
    /**
     * Robots whose last request had precedence (to guide a person, or urgent: to charge below its reserve; see
     * {@link #request(String, List, Precedence)}): they do not make way. Absent: {@link Precedence#PLAIN}.
     */
    private final Map<String, Precedence> precedence = new HashMap<>();
    private long arrivals;
    /** Arrival keys are this far apart, so that a request can be put between two queued ones (see {@link #overtaking}). */
    private static final long SPACING = 1L << 20;

    private static final class RobotState {
        final String name;
        String position;
        /** base.get(0) == position; the last is the decision point. */
        List<String> base;
        Set<Resource> holding = new LinkedHashSet<>();
        Map<Resource, Double> heldSince = new HashMap<>();
        Request pending;
        /** Why the robot is lost (its last will), or null while it works. */
        String lost;
        /**
         * Rule 3's refusals of this robot (its own requests refused as closing a cycle, and its waits withdrawn to make
         * way) since it last got through: granted the step it was last refused and then the rest of that drive to its
         * end. Its precedence by aging (see {@link #evictForTheOlder}).
         */
        int refusals;
        /** The first step of the stretch it was last refused (from, to), or null. */
        List<String> refusedStep;
        /** Whether it was granted {@link #refusedStep} since: the count ends when a grant then reaches its route's end. */
        boolean through;

        RobotState(String name, String position) {
            this.name = name;
            this.position = position;
            this.base = List.of(position);
        }

        String decisionPoint() {
            return base.get(base.size() - 1);
        }
    }

    private record Request(long arrival, String robot, List<String> stretch, List<String> horizon, Set<Resource> needed, double since,
            Set<Resource> firstBlocking) {
        Request blockedBy(Set<Resource> blocking) {
            return new Request(arrival, robot, stretch, horizon, needed, since, Set.copyOf(blocking));
        }

        Request arriving(long at) {
            return new Request(at, robot, stretch, horizon, needed, since, firstBlocking);
        }
    }

    /** What a change to the table set free: requests now granted, waiting requests now refused. */
    public record Changes(List<Granted> granted, List<Refused> refused) {
        public static final Changes NONE = new Changes(List.of(), List.of());

        public Changes {
            granted = List.copyOf(granted);
            refused = List.copyOf(refused);
        }

        public boolean isEmpty() {
            return granted.isEmpty() && refused.isEmpty();
        }

        Changes merge(Changes o) {
            List<Granted> g = new ArrayList<>(granted);
            g.addAll(o.granted);
            List<Refused> r = new ArrayList<>(refused);
            r.addAll(o.refused);
            return new Changes(g, r);
        }
    }

    public ReservationTable(TrafficMap map, DoubleSupplier clockSeconds) {
        this.map = Objects.requireNonNull(map, "map");
        this.clock = Objects.requireNonNull(clockSeconds, "clockSeconds");
        this.stats = new TrafficStats(map);
    }

    public TrafficMap map() {
        return map;
    }

    /** Seconds on the table's clock now. */
    public double now() {
        return clock.getAsDouble();
    }

    /** Waiting and holding times observed so far, and the expected wait of a step (the planner's congestion hook). */
    public TrafficStats stats() {
        return stats;
    }

    /**
     * A robot appears standing at {@code node} and holds it (and the areas around it).
     *
     * @throws IllegalStateException when the robot is already on the map or the node has no room for it (after the
     *                               robots waiting for it)
     */
    public void place(String robot, String node) {
        if (robots.containsKey(robot)) {
            throw new IllegalStateException("robot " + robot + " is already on the traffic map, at node '" + robots.get(robot).position + "'");
        }
        Set<Resource> need = map.standing(node);
        for (Resource r : need) {
            if (holders(r).size() >= r.capacity()) {
                throw new IllegalStateException("robot " + robot + " cannot be placed at node '" + node + "': " + r + " is full (held by "
                        + String.join(", ", holders(r)) + ")");
            }
            // a robot appearing where waiting robots were promised room would make them wait for it unchecked (a cycle)
            List<String> promised = queue.values().stream().filter(w -> w.needed.contains(r)).map(Request::robot).toList();
            if (holders(r).size() + promised.size() >= r.capacity()) {
                throw new IllegalStateException("robot " + robot + " cannot be placed at node '" + node + "': " + r + " is promised to "
                        + String.join(", ", promised) + ", waiting for it");
            }
        }
        RobotState s = new RobotState(robot, node);
        robots.put(robot, s);
        hold(s, need);
    }

    /**
     * Asks for the next stretch of {@code route}, which starts at the robot's decision point: granted at once,
     * queued, or refused (with the reason). A robot has at most one request at a time.
     *
     * @throws IllegalArgumentException for a route that does not start at the decision point or leaves the edges of the map
     * @throws IllegalStateException    for a robot not on the map, lost, or already waiting
     */
    public Decision request(String robot, List<String> route) {
        return request(robot, route, false);
    }

    /**
     * {@link #request(String, List)} for a robot that may be {@code guiding} a person along the route: such a robot does
     * not make way (stepping aside would leave the person behind, and it came back to the same refusal: 24 of the
     * service's 107 deadlock refusals were {@code guide(alice, c1, c4)}); when its request would close a cycle of waits,
     * the robots of the cycle that wait and guide nobody are refused instead, to make way (rule 3's guide case).
     */
    public Decision request(String robot, List<String> route, boolean guiding) {
        return request(robot, route, guiding ? Precedence.GUIDE : Precedence.PLAIN);
    }

    /**
     * {@link #request(String, List)} with the drive's {@link Precedence}: a robot guiding a person, or one driving to charge
     * below its reserve (urgent), does not make way; when its request would close a cycle of waits, the first robot of the
     * cycle that waits without precedence (and not in a dead end, where it can only come out) is refused instead, to make
     * way (rule 3's precedence case, the guide case of session 12 widened). Among robots with precedence (two guides, two
     * urgent robots, an urgent robot and a guide) nobody is displaced: the asker is refused as before.
     */
    public Decision request(String robot, List<String> route, Precedence drive) {
        Objects.requireNonNull(drive, "drive");
        RobotState s = robot(robot);
        if (s.lost != null) {
            throw new IllegalStateException("robot " + robot + " is lost (" + s.lost + ") and asks for nothing");
        }
        if (s.pending != null) {
            throw new IllegalStateException("robot " + robot + " already waits for " + s.pending.stretch + "; cancel that first");
        }
        if (drive == Precedence.PLAIN) {
            precedence.remove(robot);
        } else {
            precedence.put(robot, drive);
        }
        if (route.size() < 2) {
            throw new IllegalArgumentException("a route to request has at least two nodes, got " + route);
        }
        if (!route.get(0).equals(s.decisionPoint())) {
            throw new IllegalArgumentException("robot " + robot + "'s route starts at '" + route.get(0) + "' but its decision point is '"
                    + s.decisionPoint() + "'");
        }
        int end = nextStop(route, 0);
        if (end < route.size() - 1 && !keepsRoomToPass(route.get(end), robot)) {
            end = nextStop(route, end); // don't fill the hall: through it to the next stop node, all or nothing
        }
        if (end < route.size() - 1 && deadEndTaken(route.get(end), route.get(end + 1), robot)) {
            end = nextStop(route, end); // don't wait at the door of a taken dead end: into it, all or nothing
        }
        List<String> stretch = List.copyOf(route.subList(0, end + 1));
        Set<Resource> needed = new LinkedHashSet<>();
        for (int i = 0; i + 1 < stretch.size(); i++) {
            needed.addAll(map.step(stretch.get(i), stretch.get(i + 1)));
        }
        for (int i = end + 1; i < route.size(); i++) {
            map.step(route.get(i - 1), route.get(i)); // the horizon must be drivable too
        }
        needed.removeAll(s.holding);
        Request q = new Request(SPACING * ++arrivals, robot, stretch, List.copyOf(route.subList(end, route.size())), needed, clock.getAsDouble(), Set.of());
        Optional<String> blockedWhy = blockedReason(q);
        if (blockedWhy.isPresent()) {
            return new Refused(robot, blockedWhy.get());
        }
        if (fits(q)) {
            return grant(s, q);
        }
        List<String> cycle = cycleThrough(q);
        if (!cycle.isEmpty() && evictFromTheDoor(s, q, cycle, false)) {
            if (fits(q)) {
                return grant(s, q);
            }
            cycle = cycleThrough(q);
        }
        if (!cycle.isEmpty()) {
            Optional<Request> ahead = overtaking(q);
            if (ahead.isPresent()) {
                q = ahead.get();
                if (fits(q)) {
                    return grant(s, q);
                }
                cycle = List.of();
            }
        }
        // out of a dead end, the queue ahead tried: a robot waiting further out to go into it makes way (the dock's case)
        if (!cycle.isEmpty() && evictFromTheDoor(s, q, cycle, true)) {
            if (fits(q)) {
                return grant(s, q);
            }
            cycle = cycleThrough(q);
        }
        // a guide, or an urgent robot, does not make way: the others of the cycle do (the queue ahead tried first: nobody moves then)
        while (!cycle.isEmpty() && precedence(robot).overridesPlain() && evictForPrecedence(s, cycle)) {
            if (fits(q)) {
                return grant(s, q);
            }
            cycle = cycleThrough(q);
        }
        // nor does a robot refused more often than a waiting one of the cycle: that one does (precedence by aging)
        while (!cycle.isEmpty() && evictForTheOlder(s, cycle)) {
            if (fits(q)) {
                return grant(s, q);
            }
            cycle = cycleThrough(q);
        }
        if (!cycle.isEmpty()) {
            refused(s, stretch);
            return new Refused(robot, "deadlock avoided: " + describeCycle(cycle, q) + "; " + robot + " does not wait at " + stretch.get(0)
                    + (s.refusals > 1 ? " (refused " + s.refusals + " times in a row)" : ""), cycle);
        }
        q = q.blockedBy(new LinkedHashSet<>(waitOf(q).blocking()));
        queue.put(q.arrival, q);
        s.pending = q;
        return new Waiting(robot, waitOf(q));
    }

    /**
     * Rule 3's dead-end case: the robot asks to come out of a dead end whose door (its only way out) a robot stands at,
     * waiting to go in. Each waits for the other, and refusing the one inside would leave both where they are for good:
     * it has nowhere to go but through the door. So the one at the door is refused instead (its wait withdrawn, a
     * {@link Refused} naming both, collected for {@link #takeDisplaced}): it has somewhere else to go, and the one
     * inside queues for the door behind it. Only a wait is withdrawn, so no wait-for edge is added.
     *
     * @return whether a robot at the door was refused
     */
    private boolean evictFromTheDoor(RobotState s, Request q, List<String> cycle, boolean furtherOut) {
        String room = s.position;
        if (!room.equals(s.decisionPoint()) || map.neighbours(room).size() != 1) {
            return false;
        }
        String door = map.neighbours(room).iterator().next();
        // the one at the door; or (furtherOut, once the queue ahead did not help) one waiting further out for a stretch into
        // the room: the dock, whose door is the lobby's centre, where nobody waits, so a courier on its way to charge waits
        // at c4, which the one charging needs to come out; refusing the one inside left both there, and with the urgent
        // precedence nobody else was displaced or asked to make way
        for (String h : furtherOut ? cycle : List.copyOf(holders(map.node(door)))) {
            RobotState b = robots.get(h);
            if (h.equals(s.name) || b == null || b.lost != null || b.pending == null || !cycle.contains(h) || b.pending.stretch.size() < 2
                    || (furtherOut ? !b.pending.stretch.subList(1, b.pending.stretch.size()).contains(room)
                            : !b.decisionPoint().equals(door) || !b.pending.stretch.get(1).equals(room))) {
                continue;
            }
            String at = b.decisionPoint();
            refused(b, b.pending.stretch);
            withdraw(b);
            displaced.add(new Refused(h, "deadlock avoided: " + h + " waits at " + at + " to go into the dead end " + room + ", and "
                    + s.name + " in there can only come out through " + door + "; " + h + " makes way", List.of(h, s.name)));
            return true;
        }
        return false;
    }

    /**
     * Rule 3's precedence case: the robot guides a person, or drives to charge below its reserve (urgent), and its request
     * would close a cycle of waits. Every other robot of the cycle waits (a robot waits for another only if that one holds
     * at its decision point or queued earlier, and in a cycle each one waits in turn); the first of them without
     * precedence is refused instead (its wait withdrawn, a {@link Refused} naming both, collected for
     * {@link #takeDisplaced}) and makes way; never one waiting in a dead end, which can only come out (displaced, it had
     * nowhere to go and the asker waited for it still). Only a wait is withdrawn, so no wait-for edge is added.
     *
     * @return whether a robot of the cycle was refused
     */
    private boolean evictForPrecedence(RobotState s, List<String> cycle) {
        for (String h : cycle) {
            RobotState b = robots.get(h);
            if (h.equals(s.name) || b == null || b.lost != null || b.pending == null || precedence(h).overridesPlain()
                    || map.neighbours(b.decisionPoint()).size() == 1) {
                continue;
            }
            String at = b.decisionPoint();
            refused(b, b.pending.stretch);
            withdraw(b);
            String which = precedence(s.name) == Precedence.GUIDE ? "guides a person" : "drives to charge below its reserve";
            displaced.add(new Refused(h, "deadlock avoided: " + h + " at " + at + " and " + s.name + ", which " + which + ", would wait for each other; "
                    + h + " makes way", List.of(h, s.name)));
            return true;
        }
        return false;
    }

    /**
     * Rule 3's aging case: the robot's request would close a cycle of waits (the dead-end case, the queue ahead and the
     * guide case tried first), and a robot of the cycle that waits, guides nobody and was refused fewer times than the
     * asker (see {@link RobotState#refusals}) is refused instead (the fewest first; its wait withdrawn, a {@link Refused}
     * naming both, collected for {@link #takeDisplaced}) and makes way. Without it, rule 3 refused whoever closed the
     * cycle, and a robot coming back to the same single lane was that one every time (the benchmark's courier-3, refused
     * ten times in a row on c4-c6 until its battery was empty). Ties refuse the asker, as before, and so does a cycle
     * whose younger robots all wait in a dead end. Only a wait is withdrawn, so no wait-for edge is added.
     *
     * @return whether a robot of the cycle was refused
     */
    private boolean evictForTheOlder(RobotState s, List<String> cycle) {
        RobotState younger = null;
        for (String h : cycle) {
            RobotState b = robots.get(h);
            if (h.equals(s.name) || b == null || b.lost != null || b.pending == null || precedence(h).overridesPlain() || b.refusals >= s.refusals) {
                continue;
            }
            if (map.neighbours(b.decisionPoint()).size() == 1) {
                // it waits in a dead end (the dock): it can only come out, so making way there is the asker's to do
                // (in the 5-courier run the one at the dock was displaced, had nowhere to go, and master control then
                // asked the asker to make way after all, round after round, until the asker's battery was empty)
                continue;
            }
            if (younger == null || b.refusals < younger.refusals) {
                younger = b;
            }
        }
        if (younger == null) {
            return false;
        }
        String at = younger.decisionPoint();
        int had = younger.refusals;
        refused(younger, younger.pending.stretch);
        withdraw(younger);
        displaced.add(new Refused(younger.name, "deadlock avoided: " + younger.name + " at " + at + " and " + s.name + " would wait for each other; "
                + s.name + " was refused " + s.refusals + " times since it last got through, " + younger.name + " " + had + "; "
                + younger.name + " makes way", List.of(younger.name, s.name)));
        return true;
    }

    /** Counts a refusal by rule 3 of the robot's stretch (its own request, or its wait withdrawn to make way). */
    private static void refused(RobotState s, List<String> stretch) {
        s.refusals++;
        s.refusedStep = List.copyOf(stretch.subList(0, 2));
        s.through = false;
    }

    /** How often rule 3 refused the robot since it last got through (its precedence by aging, see {@link RobotState#refusals}). */
    public int refusals(String robot) {
        return robot(robot).refusals;
    }

    /** Whether the robot's last request was to guide a person (see {@link #request(String, List, boolean)}). */
    public boolean guiding(String robot) {
        return precedence(robot) == Precedence.GUIDE;
    }

    /** The precedence of the robot's last request ({@link Precedence#PLAIN} for a robot that asked for nothing yet). */
    public Precedence precedence(String robot) {
        return precedence.getOrDefault(robot, Precedence.PLAIN);
    }

    /**
     * The waiting requests that the last {@link #request} refused to let its robot through (rule 3's dead-end, guide and
     * aging cases: a robot at the door of the dead end the requester comes out of, robots in the way of a guide or of a
     * robot refused more often), once; the caller tells those robots, and they make way.
     */
    public List<Refused> takeDisplaced() {
        List<Refused> d = List.copyOf(displaced);
        displaced.clear();
        return d;
    }

    /** The index of the first stop node of the route after index {@code from} (or the route's last index). */
    private int nextStop(List<String> route, int from) {
        int end = from + 1;
        while (end < route.size() - 1 && !map.isStop(route.get(end))) {
            end++;
        }
        return end;
    }

    /**
     * Whether a robot stopping at {@code node} on its way through still leaves room there for one more robot
     * (one driving through, one coming out of a dead-end room): a hall for several robots is not filled by
     * robots waiting in it. A node for one robot cannot keep room, so a robot may wait there as before.
     */
    private boolean keepsRoomToPass(String node, String robot) {
        Resource r = map.node(node);
        if (r.capacity() < 2) {
            return true;
        }
        return takenByOthers(r, robot) + 2 <= r.capacity();
    }

    /** The places of {@code r} that robots other than {@code robot} hold or are queued for. */
    private int takenByOthers(Resource r, String robot) {
        int taken = 0;
        for (String h : holders(r)) {
            if (!h.equals(robot)) {
                taken++;
            }
        }
        for (Request w : queue.values()) {
            if (w.needed.contains(r) && !w.robot.equals(robot)) {
                taken++;
            }
        }
        return taken;
    }

    /**
     * Whether {@code node} is a dead end entered from {@code mouth} only (a room off a corridor) that has no room for
     * the robot now: held by others, or promised to robots queued for it. A robot waiting at its mouth would shut in
     * the robot inside, whose only way out that is.
     */
    public boolean deadEndTaken(String mouth, String node, String robot) {
        if (!map.neighbours(node).equals(Set.of(mouth))) {
            return false;
        }
        Resource r = map.node(node);
        return takenByOthers(r, robot) + 1 > r.capacity();
    }

    /** Whether {@code node} lies on the robot's base (behind or at its decision point): where it may drive. */
    public boolean released(String robot, String node) {
        return robot(robot).base.contains(node);
    }

    /** The robot's base: from the node it last passed to its decision point. */
    public List<String> base(String robot) {
        return robot(robot).base;
    }

    public String decisionPoint(String robot) {
        return robot(robot).decisionPoint();
    }

    /**
     * The robot reports it passed {@code node} of its base: what lies behind it is released, and requests
     * waiting for it may now be granted.
     *
     * @throws IllegalStateException when the node is not on its base (a robot beyond its base: see {@link #released})
     */
    public Changes passed(String robot, String node) {
        RobotState s = robot(robot);
        int at = s.base.indexOf(node);
        if (at < 0) {
            throw new IllegalStateException("robot " + robot + " reports node '" + node + "', which is not on its base " + s.base);
        }
        if (at == 0) {
            return Changes.NONE;
        }
        s.position = node;
        s.base = List.copyOf(s.base.subList(at, s.base.size()));
        rehold(s);
        return regrant();
    }

    /**
     * The robot's base ends at {@code node} from now on (its order was cancelled and it stops there): what lies
     * beyond is released, and its waiting request (if any) withdrawn.
     */
    public Changes truncate(String robot, String node) {
        RobotState s = robot(robot);
        int at = s.base.indexOf(node);
        if (at < 0) {
            throw new IllegalStateException("robot " + robot + " cannot stop at node '" + node + "', which is not on its base " + s.base);
        }
        withdraw(s);
        s.base = List.copyOf(s.base.subList(0, at + 1));
        rehold(s);
        return regrant();
    }

    /**
     * Withdraws the robot's waiting request because master control asked it to make way for a robot refused as a
     * deadlock that had nowhere to step aside to: {@link #cancel}, counted as a refusal of its stretch (its precedence by
     * aging, see {@link #evictForTheOlder}), as when the table itself withdraws a wait to make way.
     */
    public Changes makeWay(String robot) {
        RobotState s = robot(robot);
        if (s.pending == null) {
            return Changes.NONE;
        }
        refused(s, s.pending.stretch);
        withdraw(s);
        return regrant();
    }

    /** Withdraws the robot's waiting request (it waited too long, or its action was cancelled). */
    public Changes cancel(String robot) {
        RobotState s = robot(robot);
        if (s.pending == null) {
            return Changes.NONE;
        }
        withdraw(s);
        return regrant();
    }

    /**
     * The robot is lost (its last will: it is down wherever it is). Its base ahead is released, but it still
     * occupies where it stands or drives (node, edge, the areas around), so no robot is sent into it; requests
     * that need that place are refused with {@code why}. {@link #remove} clears the place when it is taken away.
     */
    public Changes lost(String robot, String why) {
        RobotState s = robot(robot);
        withdraw(s);
        s.lost = Objects.requireNonNull(why, "why");
        // it asks for nothing while lost: no precedence by age to gain (a courier with an empty battery was refused 114
        // times in a row, each counted) nor to keep, and none by its drive
        s.refusals = 0;
        s.refusedStep = null;
        s.through = false;
        precedence.remove(robot);
        Set<Resource> wreck = new LinkedHashSet<>(map.standing(s.position));
        if (s.base.size() > 1) {
            wreck.addAll(map.step(s.position, s.base.get(1)));
        }
        s.base = List.of(s.position);
        release(s, new LinkedHashSet<>(s.holding));
        hold(s, wreck);
        return refuseBlocked().merge(regrant());
    }

    /** The robot leaves the map (taken away, or shut down where it stood): everything it holds is released. */
    public Changes remove(String robot) {
        RobotState s = robot(robot);
        withdraw(s);
        precedence.remove(robot);
        release(s, new LinkedHashSet<>(s.holding));
        robots.remove(robot);
        return regrant();
    }

    /** Blocks a resource by something that is not a robot (an obstacle, a lift out of order): requests needing it are refused. */
    public Changes block(Resource r, String why) {
        blocked.put(r, Objects.requireNonNull(why, "why"));
        return refuseBlocked();
    }

    public Changes unblock(Resource r) {
        blocked.remove(r);
        return regrant();
    }

    /** Whether the robot is lost ({@link #lost}) and not yet removed. */
    public boolean isLost(String robot) {
        return robot(robot).lost != null;
    }

    /** The robots holding this resource (a lost robot too). */
    public Set<String> holders(Resource r) {
        return holders.getOrDefault(r, Set.of());
    }

    /**
     * The robots that hold the resource or wait for a stretch that needs it (in arrival order after the holders):
     * who still needs a door kept open.
     */
    public Set<String> needing(Resource r) {
        Set<String> n = new LinkedHashSet<>(holders(r));
        for (Request q : queue.values()) {
            if (q.needed.contains(r)) {
                n.add(q.robot);
            }
        }
        return n;
    }

    /** What the robot holds. */
    public Set<Resource> holding(String robot) {
        return Set.copyOf(robot(robot).holding);
    }

    public Set<String> robots() {
        return robots.keySet();
    }

    /**
     * What the robot's waiting request needs beyond what it holds (its stretch's nodes, edges and areas), or nothing when
     * it waits for nothing: the way a robot stepping aside for it must keep clear.
     */
    public Set<Resource> wanted(String robot) {
        RobotState s = robot(robot);
        return s.pending == null ? Set.of() : Set.copyOf(s.pending.needed);
    }

    /**
     * The nodes of the route the robot waits to drive (its stretch and the horizon after it), or none when it waits for
     * nothing: where it is heading, so that a robot getting out of the way does not step into its destination.
     */
    public List<String> heading(String robot) {
        RobotState s = robot(robot);
        if (s.pending == null) {
            return List.of();
        }
        List<String> route = new ArrayList<>(s.pending.stretch);
        route.addAll(s.pending.horizon.subList(1, s.pending.horizon.size()));
        return List.copyOf(route);
    }

    /** The robot's waiting request, if any, with its reason. */
    public Optional<Wait> waiting(String robot) {
        RobotState s = robot(robot);
        return s.pending == null ? Optional.empty() : Optional.of(waitOf(s.pending));
    }

    /** Every waiting request, in arrival order. */
    public List<Wait> waits() {
        return queue.values().stream().map(this::waitOf).toList();
    }

    /** The waiting requests older than {@code boundSeconds}: master control fails their actions with {@link Wait#reason()}. */
    public List<Wait> overdue(double boundSeconds) {
        double now = clock.getAsDouble();
        return waits().stream().filter(w -> w.waited(now) > boundSeconds).toList();
    }

    /**
     * Who waits for whom, the edges the no-deadlock rule keeps free of cycles: a robot waits for a robot that
     * will still hold a resource it needs when it stops (its decision point and the areas there), and for a
     * robot queued earlier for a resource it needs; both only where that resource has no room left for it.
     */
    public Map<String, Set<String>> waitsFor() {
        Map<String, Set<String>> g = new LinkedHashMap<>();
        for (Request q : queue.values()) {
            g.put(q.robot, blockersOf(q, new LinkedHashSet<>()));
        }
        return g;
    }

    /**
     * The seconds a robot asking now to drive from {@code from} to its neighbour {@code to} can expect to wait:
     * for each resource of the step without room for one more robot, the robots ahead of it (holders beyond
     * capacity and those queued for it) times the mean time one robot held it, shared among its capacity.
     * The congestion hook for planning: an edge's action cost grows with it (see the README).
     */
    public double expectedWait(String from, String to) {
        double wait = 0;
        for (Resource r : map.step(from, to)) {
            int queued = 0;
            for (Request w : queue.values()) {
                if (w.needed.contains(r)) {
                    queued++;
                }
            }
            int ahead = holders(r).size() + queued + 1 - r.capacity();
            if (blocked.containsKey(r)) {
                return Double.POSITIVE_INFINITY;
            }
            if (ahead > 0) {
                wait = Math.max(wait, ahead * stats.meanHold(r) / r.capacity());
            }
        }
        return wait;
    }

    // ---- the rule ------------------------------------------------------------------------------

    /** Room for every resource the request needs after the robots queued earlier for it have theirs. */
    private boolean fits(Request q) {
        for (Resource r : q.needed) {
            if (!room(r, q)) {
                return false;
            }
        }
        return true;
    }

    private boolean room(Resource r, Request q) {
        int earlier = 0;
        for (Request w : queue.headMap(q.arrival, false).values()) {
            if (w.needed.contains(r)) {
                earlier++;
            }
        }
        return holders(r).size() + earlier + 1 <= r.capacity();
    }

    private Set<String> blockersOf(Request q, Set<Resource> blockingOut) {
        Set<String> out = new LinkedHashSet<>();
        for (Resource r : q.needed) {
            if (room(r, q)) {
                continue;
            }
            blockingOut.add(r);
            for (String h : holders(r)) {
                RobotState hs = robots.get(h);
                if (!h.equals(q.robot) && hs.lost == null && map.standing(hs.decisionPoint()).contains(r)) {
                    out.add(h);
                }
            }
            for (Request w : queue.headMap(q.arrival, false).values()) {
                if (w.needed.contains(r)) {
                    out.add(w.robot);
                }
            }
        }
        return out;
    }

    /**
     * The request put ahead of queued ones, as late as possible, where the wait-for graph stays free of cycles,
     * or empty when there is no such place. A robot that the earlier ones wait for (it stands in their way)
     * goes first instead of being refused: they need it gone, and it needs them to let it pass.
     */
    private Optional<Request> overtaking(Request q) {
        List<Long> keys = new ArrayList<>(queue.keySet());
        for (int i = keys.size() - 1; i >= 0; i--) {
            long before = keys.get(i);
            long after = i == 0 ? 0 : keys.get(i - 1);
            if (before - after < 2) {
                continue;
            }
            Request moved = q.arriving(after + (before - after) / 2);
            queue.put(moved.arrival, moved);
            boolean acyclic = acyclic(waitsFor());
            queue.remove(moved.arrival);
            if (acyclic) {
                return Optional.of(moved);
            }
        }
        return Optional.empty();
    }

    /** Whether the graph has no cycle (depth first, three colours). */
    private static boolean acyclic(Map<String, Set<String>> g) {
        Map<String, Integer> colour = new HashMap<>();
        for (String start : g.keySet()) {
            if (colour.containsKey(start)) {
                continue;
            }
            Deque<java.util.Iterator<String>> stack = new ArrayDeque<>();
            Deque<String> path = new ArrayDeque<>();
            colour.put(start, 1);
            path.push(start);
            stack.push(g.getOrDefault(start, Set.of()).iterator());
            while (!stack.isEmpty()) {
                java.util.Iterator<String> it = stack.peek();
                if (it.hasNext()) {
                    String next = it.next();
                    Integer c = colour.get(next);
                    if (c == null) {
                        colour.put(next, 1);
                        path.push(next);
                        stack.push(g.getOrDefault(next, Set.of()).iterator());
                    } else if (c == 1) {
                        return false;
                    }
                } else {
                    stack.pop();
                    colour.put(path.pop(), 2);
                }
            }
        }
        return true;
    }

    /** The cycle of waits queuing {@code q} would close (robot names, q's robot first), or empty. */
    private List<String> cycleThrough(Request q) {
        Map<String, Set<String>> g = waitsFor();
        g.put(q.robot, blockersOf(q, new LinkedHashSet<>()));
        Map<String, String> parent = new HashMap<>();
        Deque<String> todo = new ArrayDeque<>();
        Set<String> seen = new HashSet<>();
        todo.add(q.robot);
        while (!todo.isEmpty()) {
            String at = todo.poll();
            for (String next : g.getOrDefault(at, Set.of())) {
                if (next.equals(q.robot)) {
                    List<String> cycle = new ArrayList<>();
                    for (String c = at; c != null; c = parent.get(c)) {
                        cycle.add(0, c);
                    }
                    return cycle;
                }
                if (seen.add(next)) {
                    parent.put(next, at);
                    todo.add(next);
                }
            }
        }
        return List.of();
    }

    private String describeCycle(List<String> cycle, Request q) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < cycle.size(); i++) {
            String from = cycle.get(i);
            String to = cycle.get((i + 1) % cycle.size());
            Request r = from.equals(q.robot) ? q : robots.get(from).pending;
            Set<Resource> blocking = new LinkedHashSet<>();
            blockersOf(r, blocking);
            Set<Resource> held = new LinkedHashSet<>(blocking);
            held.retainAll(robots.get(to).holding);
            if (i > 0) {
                b.append(", ");
            }
            b.append(from).append(" would wait for ").append(to)
                    .append(held.isEmpty() ? " (queued ahead)" : " (" + String.join(", ", held.stream().map(Resource::toString).toList()) + ")");
        }
        return b.toString();
    }

    /** The first blocked resource the request needs, areas first (the corridor says more than its lane). */
    private Optional<String> blockedReason(Request q) {
        List<Resource> areasFirst = new ArrayList<>(q.needed);
        areasFirst.sort(java.util.Comparator.comparing((Resource r) -> !r.kind().isArea()));
        for (Resource r : areasFirst) {
            if (blocked.containsKey(r)) {
                return Optional.of(r + " is blocked: " + blocked.get(r));
            }
            List<String> wrecks = holders(r).stream().filter(h -> robots.get(h).lost != null).toList();
            if (!wrecks.isEmpty() && wrecks.size() >= r.capacity()) {
                String h = wrecks.get(0);
                return Optional.of(r + " is blocked by robot " + h + ", lost there (" + robots.get(h).lost + ")");
            }
        }
        return Optional.empty();
    }

    private Granted grant(RobotState s, Request q) {
        if (s.refusedStep != null && Collections.indexOfSubList(q.stretch, s.refusedStep) >= 0) {
            s.through = true;
        }
        if (s.through && q.horizon.size() <= 1) {
            // through where it was refused and on to the end of that drive: its precedence is spent (a step aside, also
            // a grant to a route's end, does not end it; nor does getting through one place of a drive only to meet the
            // next robot at the next one, as the benchmark's courier-3 did on its way to the dock)
            s.refusals = 0;
            s.refusedStep = null;
            s.through = false;
        }
        List<String> base = new ArrayList<>(s.base);
        base.addAll(q.stretch.subList(1, q.stretch.size()));
        s.base = List.copyOf(base);
        rehold(s);
        return new Granted(s.name, q.stretch, q.horizon.size() > 1 ? q.horizon : List.of());
    }

    /** Grants the waiting requests that now fit, in arrival order. */
    private Changes regrant() {
        List<Granted> granted = new ArrayList<>();
        boolean again = true;
        while (again) {
            again = false;
            for (Request q : List.copyOf(queue.values())) {
                if (fits(q)) {
                    queue.remove(q.arrival);
                    RobotState s = robots.get(q.robot);
                    s.pending = null;
                    stats.waited(q.firstBlocking, clock.getAsDouble() - q.since);
                    granted.add(grant(s, q));
                    again = true;
                    break;
                }
            }
        }
        return new Changes(granted, List.of());
    }

    private Changes refuseBlocked() {
        List<Refused> refused = new ArrayList<>();
        for (Request q : List.copyOf(queue.values())) {
            Optional<String> why = blockedReason(q);
            if (why.isPresent()) {
                withdraw(robots.get(q.robot));
                refused.add(new Refused(q.robot, why.get()));
            }
        }
        return new Changes(List.of(), refused).merge(regrant());
    }

    private void withdraw(RobotState s) {
        if (s.pending != null) {
            queue.remove(s.pending.arrival);
            s.pending = null;
        }
    }

    /** Holds exactly what the robot's position and base cover. */
    private void rehold(RobotState s) {
        Set<Resource> want = new LinkedHashSet<>(map.standing(s.position));
        for (int i = 0; i + 1 < s.base.size(); i++) {
            want.addAll(map.step(s.base.get(i), s.base.get(i + 1)));
        }
        Set<Resource> gone = new LinkedHashSet<>(s.holding);
        gone.removeAll(want);
        release(s, gone);
        want.removeAll(s.holding);
        hold(s, want);
    }

    private void hold(RobotState s, Set<Resource> rs) {
        double now = clock.getAsDouble();
        for (Resource r : rs) {
            if (s.holding.add(r)) {
                holders.computeIfAbsent(r, k -> new LinkedHashSet<>()).add(s.name);
                s.heldSince.put(r, now);
            }
        }
    }

    private void release(RobotState s, Set<Resource> rs) {
        double now = clock.getAsDouble();
        for (Resource r : rs) {
            if (s.holding.remove(r)) {
                Set<String> h = holders.get(r);
                h.remove(s.name);
                if (h.isEmpty()) {
                    holders.remove(r);
                }
                stats.held(r, now - s.heldSince.remove(r));
            }
        }
    }

    private Wait waitOf(Request q) {
        Set<Resource> blocking = new LinkedHashSet<>();
        Set<String> blockers = new LinkedHashSet<>();
        for (Resource r : q.needed) {
            if (!room(r, q)) {
                blocking.add(r);
                blockers.addAll(holders(r));
                for (Request w : queue.headMap(q.arrival, false).values()) {
                    if (w.needed.contains(r)) {
                        blockers.add(w.robot);
                    }
                }
            }
        }
        blockers.remove(q.robot);
        return new Wait(q.robot, q.stretch, q.since, List.copyOf(blocking), List.copyOf(blockers));
    }

    private RobotState robot(String robot) {
        RobotState s = robots.get(robot);
        if (s == null) {
            throw new IllegalStateException("robot " + robot + " is not on the traffic map (place it first)");
        }
        return s;
    }
}
