package org.triad.vda5050.master;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.function.Consumer;

import org.triad.building.traffic.Decision;
import org.triad.building.traffic.Decision.Granted;
import org.triad.building.traffic.Decision.Refused;
import org.triad.building.traffic.Precedence;
import org.triad.building.traffic.Wait;
import org.triad.vda5050.protocol.AgvState;
import org.triad.vda5050.protocol.Messages.Action;
import org.triad.vda5050.protocol.Messages.ActionState;
import org.triad.vda5050.protocol.Messages.ActionStatus;
import org.triad.vda5050.protocol.Messages.AgvError;
import org.triad.vda5050.protocol.Messages.Edge;
import org.triad.vda5050.protocol.Messages.Node;

/**
 * One route driven under traffic control as one VDA 5050 order: the reserved part is the order's base, the
 * rest its horizon; each stretch traffic control grants later extends the base with an order update (same
 * orderId, next orderUpdateId, stitched at the old decision point); what the AGV reports passed is released
 * behind it. The base is kept one stretch ahead of the robot: as it enters its last granted stretch, the
 * next is asked for, so a robot with a free path never reaches a decision point without its continuation.
 * Sequence ids: node {@code i} of the route is {@code 2i}, the edge after it {@code 2i+1}.
 */
final class RouteDrive {
    /**
     * What one state means for the call: still running, done, or failed with a reason; {@code congestion} when traffic
     * control gave up on the drive (a deadlock avoided, a wait over the bound, made way), not the robot or a device.
     */
    record Verdict(boolean done, String failure, boolean congestion) {
        static final Verdict RUNNING = new Verdict(false, null);
        static final Verdict DONE = new Verdict(true, null);

        Verdict(boolean done, String failure) {
            this(done, failure, false);
        }
    }

    /** Sends an order message (orderId, orderUpdateId, nodes, edges are what differs). */
    interface OrderSender {
        void send(String orderId, int orderUpdateId, List<Node> nodes, List<Edge> edges);
    }

    private final String robot;
    private final List<String> route;
    private final String orderId;
    private final TrafficControl traffic;
    private final OrderSender orders;
    private final Consumer<String> stopNow;
    /** The action done along each edge (e.g. guiding a person, riding the lift), one per edge (null: none), or empty. */
    private final List<Action> edgeActions;
    /** Whether the robot drives to charge below its reserve (see {@link Precedence#URGENT}). */
    private final boolean urgent;
    private final List<Integer> stretchEnds = new ArrayList<>();
    private int updateId = -1;
    private int baseEnd;
    private int passed;
    private boolean waiting;
    /** The AGV failed driving an edge (its error names one): it may stand between two nodes. */
    private boolean strandedOnEdge;
    /** The drive ended at its decision point (refused, a wait over the bound, a door shut): the AGV drives on to it. */
    private boolean endedHere;
    /** The drive ended to make way for another robot (one refused as a deadlock, or one coming out of a dead end). */
    private boolean madeWay;
    /** Traffic control's refusal that ended the drive, if one did. */
    private Refused refusal;
    /** The drive ended because its wait went over the bound. */
    private boolean waitedInVain;

    /**
     * @param stopNow sends the AGV an instant action that stops it at once (its argument the reason)
     */
    RouteDrive(String robot, List<String> route, String orderId, TrafficControl traffic, OrderSender orders, Consumer<String> stopNow) {
        this(robot, route, orderId, traffic, orders, stopNow, List.of());
    }

    /**
     * @param edgeActions one action per edge of the route (done while the robot drives it, e.g. guiding a person; null for
     *                    none), or empty
     */
    RouteDrive(String robot, List<String> route, String orderId, TrafficControl traffic, OrderSender orders, Consumer<String> stopNow,
            List<Action> edgeActions) {
        this(robot, route, orderId, traffic, orders, stopNow, edgeActions, false);
    }

    /** @param urgent whether the robot drives to charge below its reserve: it does not make way (rule 3's precedence case) */
    RouteDrive(String robot, List<String> route, String orderId, TrafficControl traffic, OrderSender orders, Consumer<String> stopNow,
            List<Action> edgeActions, boolean urgent) {
        this.urgent = urgent;
        if (!edgeActions.isEmpty() && edgeActions.size() != route.size() - 1) {
            throw new IllegalArgumentException("one edge action per edge of " + route + ", not " + edgeActions.size());
        }
        this.edgeActions = java.util.Collections.unmodifiableList(new ArrayList<>(edgeActions));
        this.robot = robot;
        this.route = List.copyOf(route);
        this.orderId = orderId;
        this.traffic = traffic;
        this.orders = orders;
        this.stopNow = stopNow;
    }

    String orderId() {
        return orderId;
    }

    /** Whether the drive ended to make way for another robot (it steps aside next). */
    boolean madeWay() {
        return madeWay;
    }

    /** The refusal that ended the drive (e.g. a deadlock avoided, naming the robots of the cycle), if one did. */
    Optional<Refused> refusal() {
        return Optional.ofNullable(refusal);
    }

    /** Asks for the first stretches and sends the order (its base possibly just the start node); a reason when refused. */
    Optional<String> start() {
        Decision d = traffic.request(robot, route, precedence());
        if (d instanceof Refused r) {
            refusal = r;
            return Optional.of(r.reason());
        }
        if (d instanceof Granted g) {
            Optional<String> shut = traffic.openDoors(robot, g.stretch());
            if (shut.isPresent()) {
                return shut;
            }
            baseEnd = g.stretch().size() - 1;
            stretchEnds.add(baseEnd);
        } else {
            waiting = true;
        }
        send(0);
        if (waiting) {
            return Optional.empty();
        }
        Optional<String> ahead = askAhead();
        if (ahead.isPresent()) {
            // the order with its first stretch released is out: the AGV drives it whatever the call does, so the order is
            // ended at the decision point and the base kept up to there, as for a refusal later on. Before, the caller cut
            // the base back to the start node while the AGV drove on, stopped at the decision point waiting for an update
            // that never came (its order never ended, every later order rejected as "still executing"), and the table gave
            // its place to others: courier-8 stood at c1 for 400 simulated s, the map had it at c0, and courier-6, granted
            // c1, was blocked by it there (the benchmark's longest standstill)
            endHere(ahead.get(), deadlockAvoided());
        }
        return ahead;
    }

    /** Whether the drive ended because its wait for the next stretch went over the bound. */
    boolean waitedInVain() {
        return waitedInVain;
    }

    /** Whether the drive ended at its decision point with its order sent (the AGV still drives there: see {@link #trail}). */
    boolean endedAtDecisionPoint() {
        return endedHere;
    }

    /** Called with each state of the AGV (and again every few milliseconds with the last one). */
    Verdict onState(AgvState s) {
        if (traffic.isLost(robot)) {
            return new Verdict(false, "traffic control lost AGV " + robot);
        }
        if (orderId.equals(s.orderId())) {
            // the AGV's own failure first: a stretch granted meanwhile would otherwise be sent as an order update stitched
            // at the decision point, which the AGV, its order already aborted where it stopped, rejects (noRouteError: the
            // order starts at c6 but the AGV is at c3), and that rejection, not the failure, became the drive's reason
            for (AgvError e : s.errors()) {
                if (orderId.equals(e.reference("orderId"))) {
                    strandedOnEdge = e.reference("edgeId") != null;
                    return new Verdict(false, e.describe());
                }
            }
        }
        Optional<Decision> d = traffic.take(robot);
        if (d.isPresent() && waiting) {
            waiting = false;
            if (d.get() instanceof Refused r) {
                refusal = r;
                madeWay = traffic.displaced(robot);
                return endHere(r.reason(), deadlockAvoided());
            }
            Optional<String> shut = extend((Granted) d.get());
            if (shut.isPresent()) {
                return endHere(shut.get(), false);
            }
        }
        if (waiting && traffic.makeWay(robot)) {
            waiting = false;
            madeWay = true;
            return endHere("traffic control: " + robot + " made way (a robot refused as a deadlock had nowhere to step aside to)", true);
        }
        Optional<Wait> late = traffic.overdue(robot);
        if (late.isPresent()) {
            waiting = false;
            waitedInVain = true;
            return endHere(String.format(Locale.ROOT, "%s for more than %.1f s (the wait bound)", late.get().reason(), traffic.waitBoundSeconds()), true);
        }
        if (!orderId.equals(s.orderId())) {
            return Verdict.RUNNING;
        }
        int at = s.lastNodeSequenceId() / 2;
        if (s.lastNodeSequenceId() % 2 == 0 && at < route.size() && route.get(at).equals(s.lastNodeId()) && at > passed) {
            if (at > baseEnd) {
                String why = String.format(Locale.ROOT, "safety: AGV %s drove beyond its released base: it reports node '%s' (sequence %d) but its base ends at '%s' (sequence %d); stopped",
                        robot, s.lastNodeId(), s.lastNodeSequenceId(), route.get(baseEnd), 2 * baseEnd);
                stopNow.accept(why);
                traffic.rogue(robot, s.lastNodeId(), why);
                return new Verdict(false, why);
            }
            for (int i = passed + 1; i <= at; i++) {
                traffic.passed(robot, route.get(i));
            }
            passed = at;
            Optional<String> refused = askAhead();
            if (refused.isPresent()) {
                return endHere(refused.get(), deadlockAvoided());
            }
        }
        for (Action a : edgeActions) {
            if (a == null) {
                continue;
            }
            Optional<ActionState> as = s.actionState(a.actionId());
            if (as.isPresent() && as.get().actionStatus() == ActionStatus.FAILED) {
                traffic.stopAt(robot, route.get(Math.min(passed + 1, baseEnd))); // it may stand on the edge after the node it passed
                return new Verdict(false, a.actionType() + " failed" + (as.get().resultDescription() == null ? "" : ": " + as.get().resultDescription()));
            }
        }
        boolean actionsDone = edgeActions.stream().filter(java.util.Objects::nonNull)
                .allMatch(a -> s.actionState(a.actionId()).map(as -> as.actionStatus() == ActionStatus.FINISHED).orElse(false));
        if (passed == route.size() - 1 && s.nodeStates().isEmpty() && s.edgeStates().isEmpty() && !s.driving() && actionsDone) {
            return Verdict.DONE;
        }
        return Verdict.RUNNING;
    }

    /**
     * The call failed: ended at its decision point (see {@link #endHere}), the AGV keeps its base up to there; after the AGV's error on an edge its reservations end at the node after the
     * one it last reported (it may stand between them), after its silence at the one it reported; after its last will (not back within the grace) it is lost there, its base ahead freed.
     */
    void abandon(boolean connectionLost) {
        if (connectionLost) {
            traffic.lost(robot, "CONNECTIONBROKEN (its last will) and not back within the reconnect grace");
        } else if (endedHere) {
            // its order ends at the decision point, which it still drives to: its base stays reserved up to there (cut
            // back to the node it last reported, the AGV would drive on through places given to others)
            return;
        } else if (strandedOnEdge) {
            // it stopped on the edge after the node it passed: it keeps that edge and the node ahead until it reports
            // where it stands (backed off to the node behind it, or at the one ahead), so nobody is sent into it
            traffic.stopAt(robot, route.get(Math.min(passed + 1, baseEnd)));
        } else {
            traffic.stopAt(robot, route.get(passed));
        }
    }

    /**
     * After the call ended at its decision point ({@link #endHere}) the AGV still drives there: the nodes it reports on
     * the way are passed on to traffic control as before, so that what lies behind it is released. Without this the
     * robot stood at its decision point still holding the nodes behind it (up to its whole last stretch), and a robot
     * waiting for one of them waited for it with no edge in the wait-for graph (the table takes a robot to hold only its
     * decision point once stopped): four couriers stood in a ring that deadlock avoidance did not see. True once there
     * is nothing more to report (the AGV at its decision point, or on another order).
     */
    synchronized boolean trail(AgvState s) {
        if (!endedHere || passed >= baseEnd) {
            return true;
        }
        if (!orderId.equals(s.orderId())) {
            return true;
        }
        int at = s.lastNodeSequenceId() / 2;
        if (s.lastNodeSequenceId() % 2 == 0 && at <= baseEnd && at < route.size() && route.get(at).equals(s.lastNodeId()) && at > passed) {
            for (int i = passed + 1; i <= at; i++) {
                traffic.passedIfReleased(robot, route.get(i));
            }
            passed = at;
        }
        return passed >= baseEnd || s.nodeStates().isEmpty() && s.edgeStates().isEmpty() && !s.driving();
    }

    /** Asks for further stretches while the robot is in its last granted one; a reason when refused. */
    private Optional<String> askAhead() {
        while (!waiting && baseEnd < route.size() - 1 && stretchEnds.stream().filter(e -> e > passed).count() <= 1) {
            Decision d = traffic.request(robot, route.subList(baseEnd, route.size()), precedence());
            if (d instanceof Refused r) {
                refusal = r;
                return Optional.of(r.reason());
            }
            if (d instanceof Granted g) {
                Optional<String> shut = extend(g);
                if (shut.isPresent()) {
                    return shut;
                }
            } else {
                waiting = true;
            }
        }
        return Optional.empty();
    }

    /** Opens the stretch's doors, then releases it to the AGV; the reason when a door stays shut (nothing released). */
    private Optional<String> extend(Granted g) {
        Optional<String> shut = traffic.openDoors(robot, g.stretch());
        if (shut.isPresent()) {
            return shut;
        }
        int from = baseEnd;
        baseEnd += g.stretch().size() - 1;
        stretchEnds.add(baseEnd);
        send(from);
        return Optional.empty();
    }

    /**
     * What the drive asks of rule 3: urgent on the way to charge below its reserve (it would run flat in the others' way),
     * a guide when it guides a person (the person would be left behind); either does not make way.
     */
    Precedence precedence() {
        if (urgent) {
            return Precedence.URGENT;
        }
        return edgeActions.stream().anyMatch(a -> a != null && a.actionType().equals("guide")) ? Precedence.GUIDE : Precedence.PLAIN;
    }

    /** Whether traffic control refused the drive to avoid a deadlock (a refusal naming a cycle; a blocked place names none). */
    boolean deadlockAvoided() {
        return refusal != null && !refusal.cycle().isEmpty();
    }

    /** Ends the order at the robot's decision point (the horizon deleted) and fails the call with the reason. */
    private Verdict endHere(String why, boolean congestion) {
        endedHere = true;
        orders.send(orderId, ++updateId, List.of(node(baseEnd)), List.of());
        traffic.stopAt(robot, route.get(baseEnd));
        return new Verdict(false, why, congestion);
    }

    /** The order (update) from route node {@code from} on: released up to the decision point, horizon after. */
    private void send(int from) {
        List<Node> nodes = new ArrayList<>();
        List<Edge> edges = new ArrayList<>();
        for (int i = from; i < route.size(); i++) {
            nodes.add(node(i));
            if (i + 1 < route.size()) {
                edges.add(new Edge(route.get(i) + "-" + route.get(i + 1), 2 * i + 1, null, i + 1 <= baseEnd, route.get(i), route.get(i + 1),
                        edgeActions.isEmpty() || edgeActions.get(i) == null ? List.of() : List.of(edgeActions.get(i))));
            }
        }
        orders.send(orderId, ++updateId, nodes, edges);
    }

    private Node node(int i) {
        return new Node(route.get(i), 2 * i, null, i <= baseEnd, null, List.of());
    }
}
