package org.triad.vda5050.master;

import java.util.ArrayList;
import java.util.Objects;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BooleanSupplier;
import java.util.function.Function;

import com.fasterxml.jackson.databind.JsonNode;

import org.triad.runtime.app.Failure;
import org.triad.runtime.app.FailureExplaining;
import org.triad.vda5050.mqtt.MqttLink;
import org.triad.vda5050.mqtt.Received;
import org.triad.vda5050.protocol.AgvState;
import org.triad.vda5050.protocol.Connection;
import org.triad.vda5050.protocol.Header;
import org.triad.vda5050.protocol.HeaderIds;
import org.triad.vda5050.protocol.InstantActions;
import org.triad.vda5050.protocol.Messages.Action;
import org.triad.vda5050.protocol.Messages.ActionParameter;
import org.triad.vda5050.protocol.Messages.ActionState;
import org.triad.vda5050.protocol.Messages.ActionStatus;
import org.triad.vda5050.protocol.Messages.AgvError;
import org.triad.vda5050.protocol.Messages.BlockingType;
import org.triad.vda5050.protocol.Messages.ConnectionState;
import org.triad.vda5050.protocol.Messages.Edge;
import org.triad.vda5050.protocol.Messages.Node;
import org.triad.vda5050.protocol.Order;
import org.triad.vda5050.protocol.Topic;

/**
 * One AGV as master control sees it: the last state and connection it reported, and blocking calls that
 * send it an order or instant action and wait until the AGV reports it finished, failed or rejected it,
 * fell silent, or lost its connection. Each call returns whether it succeeded; {@link #lastFailure()} says
 * why not, in words for RefArc's Status. Robotics experts implement {@code IRobot} in a few lines on it:
 *
 * <pre>{@code
 * public boolean move(WayPoint src, WayPoint dst) { return agv.drive(src.name(), dst.name()); }
 * public boolean pick(Item i, WayPoint w) { return agv.nodeAction(w.name(), "pick", Map.of("loadId", i.name())); }
 * public WayPoint loc() { return objects.waypoint(agv.state().orElseThrow().lastNodeId()); }
 * }</pre>
 *
 * Orders get ids unique to this master ({@code triad-<session>-<n>}), so an AGV that receives one twice
 * (QoS 1 after a broker restart) recognises the duplicate by orderId and orderUpdateId.
 */
public final class RemoteAgv implements FailureExplaining {
    private static final String SESSION = Long.toHexString(System.currentTimeMillis() & 0xffffffffL);
    private static final AtomicInteger IDS = new AtomicInteger();

    private final MqttLink link;
    private final String manufacturer;
    private final String serialNumber;
    private final VdaTimeouts timeouts;
    private final HeaderIds headerIds = new HeaderIds();
    private final Object lock = new Object();
    private AgvState state;
    private long stateNanos;
    private ConnectionState connection;
    private long connectionNanos;
    private long masterReconnectNanos;
    private JsonNode factsheet;
    private final StateScreen screen;
    private String lastFailure;
    /** The kind of {@link #lastFailure}: traffic control's congestion, or a fault. */
    private Failure.Cause lastCause = Failure.Cause.FAULT;
    private long orderToFirstState = -1;
    /** An order this master gave up on (silence, a broken connection, a timeout) that the AGV may still be running. */
    private String abandonedOrder;
    /** A drive whose call ended at its decision point while the AGV still drives there: its nodes are still reported. */
    private RouteDrive trailing;
    /** The traffic control the AGV last drove under (it stands on its map), or null. */
    private TrafficControl traffic;
    /** Whether a {@link #driveRoute} call runs (it tells traffic control of a lost connection itself). */
    private boolean drivingRoute;
    /** Checks, one reconnect grace after a last will, whether an idle AGV came back (a daemon shared by every AGV). */
    private static final ScheduledExecutorService IDLE_WATCH = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "triad-traffic-idle-watch");
        t.setDaemon(true);
        return t;
    });

    RemoteAgv(MqttLink link, String manufacturer, String serialNumber, VdaTimeouts timeouts, java.util.function.Consumer<String> log) {
        this.link = link;
        this.manufacturer = manufacturer;
        this.serialNumber = serialNumber;
        this.timeouts = timeouts;
        this.screen = new StateScreen(manufacturer + "/" + serialNumber, log);
    }

    public String serialNumber() {
        return serialNumber;
    }

    public String manufacturer() {
        return manufacturer;
    }

    /** {@code triad/courier-1}. */
    public String name() {
        return manufacturer + "/" + serialNumber;
    }

    /** The last state the AGV reported, if any. */
    public Optional<AgvState> state() {
        synchronized (lock) {
            return Optional.ofNullable(state);
        }
    }

    /** The last connection state the AGV reported (its last will included), if any. */
    public Optional<ConnectionState> connection() {
        synchronized (lock) {
            return Optional.ofNullable(connection);
        }
    }

    /** The last factsheet the AGV published, if any. */
    public Optional<JsonNode> factsheet() {
        synchronized (lock) {
            return Optional.ofNullable(factsheet);
        }
    }

    /** Wall-clock nanoseconds from the last order sent to the first state acknowledging it (its orderId), or -1. */
    public long lastOrderAcknowledgedNanos() {
        synchronized (lock) {
            return orderToFirstState;
        }
    }

    @Override
    public Optional<String> lastFailure() {
        synchronized (lock) {
            return Optional.ofNullable(lastFailure);
        }
    }

    @Override
    public Optional<Failure> lastFailureWithCause() {
        synchronized (lock) {
            return Optional.ofNullable(lastFailure).map(why -> new Failure(why, lastCause));
        }
    }

    /**
     * Waits until the AGV has reported a state while ONLINE: up to the online timeout for an AGV not heard
     * from yet, up to the reconnect grace for one whose connection is known broken or offline.
     */
    public boolean awaitOnline() {
        boolean knownDown;
        synchronized (lock) {
            knownDown = down();
        }
        return await(() -> state != null && !down(), knownDown ? timeouts.reconnectGraceSeconds() : timeouts.onlineSeconds());
    }

    /**
     * Whether the AGV is down as far as this master can tell: its last connection message says
     * CONNECTIONBROKEN or OFFLINE and no state has come from it since. A connection message alone does
     * not decide it, because a CONNECTIONBROKEN reaches master control while the AGV is fine: a broker
     * that is stopped publishes the last will of every client still connected (Mosquitto does, on
     * SIGTERM) and keeps it as the retained message, so after the restart master control gets it again
     * (as a QoS 1 redelivery and as the retained message of its renewed subscription) in an order
     * relative to the AGV's re-announced ONLINE that depends on who reconnects first. A will's headerId
     * and timestamp are set at connect time and are outdated by definition (VDA 5050 6.14), so they
     * cannot order it either. A state can only come from an AGV that is connected, so a state received
     * after the connection message wins. Call with the lock held.
     */
    private boolean down() {
        return (connection == ConnectionState.CONNECTIONBROKEN || connection == ConnectionState.OFFLINE) && connectionNanos >= stateNanos;
    }

    /**
     * For how long the AGV has been down as far as this master can tell (see {@link #awaitOnline()}), in
     * seconds; 0 while it is not, and while this master is disconnected itself (the AGV cannot be judged
     * then), counting from this master's reconnection when that came later (after a broker restart the
     * AGV's ONLINE follows ours).
     */
    public double secondsDown() {
        synchronized (lock) {
            if (!down() || !link.isConnected()) {
                return 0;
            }
            return (System.nanoTime() - Math.max(connectionNanos, masterReconnectNanos)) / 1e9;
        }
    }

    /**
     * Waits until the AGV's state shows no order in progress (no node or edge states, not driving), at most
     * {@code seconds}, less if it falls silent for the state timeout: called between this master's own
     * orders, it waits for an order that another master control sent before (a service killed mid-order and
     * started again), so that what is read next is where that order left the AGV, not where it began.
     * Returns whether the AGV is at rest.
     */
    public boolean awaitAtRest(double seconds) {
        long began = System.nanoTime();
        return await(() -> state == null || state.nodeStates().isEmpty() && state.edgeStates().isEmpty() && !state.driving()
                || System.nanoTime() - Math.max(began, stateNanos) > seconds(timeouts.stateSeconds()), seconds)
                && state().map(s -> s.nodeStates().isEmpty() && s.edgeStates().isEmpty() && !s.driving()).orElse(true);
    }

    /** Whether the AGV reports state and its connection is not known broken (see {@link #awaitOnline()}). */
    public boolean isOnline() {
        synchronized (lock) {
            return state != null && !down();
        }
    }

    /** Drives from node {@code from} (where the AGV is) along the edge to node {@code to}: an order of two nodes and an edge. */
    public boolean drive(String from, String to) {
        return traverse(from, to, null, Map.of());
    }

    /**
     * Drives from {@code from} to {@code to} doing {@code edgeActionType} (with these parameters) on the way,
     * e.g. guiding a person; with a null action type a plain drive.
     */
    public boolean traverse(String from, String to, String edgeActionType, Map<String, ?> parameters) {
        List<Action> edgeActions = edgeActionType == null ? List.of() : List.of(action(edgeActionType, parameters));
        String orderId = nextId("order");
        List<Node> nodes = List.of(new Node(from, 0, null, true, null, List.of()), new Node(to, 2, null, true, null, List.of()));
        List<Edge> edges = List.of(new Edge(from + "-" + to, 1, null, true, from, to, edgeActions));
        return runOrder(orderId, nodes, edges, edgeActions, describeCall(edgeActionType == null ? "drive" : edgeActionType, from, to));
    }

    /** Runs one action at a node (where the AGV is): an order of that node carrying the action with these parameters. */
    public boolean nodeAction(String node, String actionType, Map<String, ?> parameters) {
        Action a = action(actionType, parameters);
        String orderId = nextId("order");
        return runOrder(orderId, List.of(new Node(node, 0, null, true, null, List.of(a))), List.of(), List.of(a),
                describeCall(actionType, node, null));
    }

    /** Sends an instant action (outside any order) and waits for its action state to finish or fail. */
    public boolean instantAction(String actionType, Map<String, ?> parameters) {
        Action a = action(actionType, parameters);
        String call = "instant action " + actionType;
        if (!ready(call)) {
            return false;
        }
        long sent = System.nanoTime();
        publish(Topic.INSTANT_ACTIONS, new InstantActions(headerIds.next(Topic.INSTANT_ACTIONS), HeaderIds.now(), Header.VERSION,
                manufacturer, serialNumber, List.of(a)));
        return awaitOutcome(call, sent, s -> {
            Optional<ActionState> as = s.actionState(a.actionId());
            if (as.isEmpty()) {
                return Outcome.PENDING;
            }
            if (as.get().actionStatus() == ActionStatus.FAILED) {
                return Outcome.failed(actionType + " failed" + result(as.get()));
            }
            return as.get().actionStatus() == ActionStatus.FINISHED ? Outcome.DONE : Outcome.PENDING;
        }, null);
    }

    /**
     * Drives {@code route} (node ids, the first where the AGV stands) under traffic control, as one order whose
     * base is what {@code traffic} reserved for it and whose horizon is the rest; the base grows by order
     * updates as further stretches are granted, and what the AGV passes is released behind it. Waiting for a
     * resource is not a failure; the call fails when traffic control refuses a stretch (a wait that would
     * deadlock, a place blocked by a lost robot or an obstacle), when the robot waits longer than the bound
     * (the reason names what it waited for and who held it), when the AGV drives beyond its base (a safety
     * error: it is stopped at once with {@code startPause}), and for every reason {@link #drive} fails.
     */
    public boolean driveRoute(List<String> route, TrafficControl traffic) {
        return driveRoute(route, traffic, null, Map.of());
    }

    /**
     * {@link #driveRoute(List, TrafficControl)} doing {@code edgeActionType} (with these parameters) along every
     * edge of the route, e.g. guiding a person: the call succeeds once the robot has arrived and every edge's
     * action finished; with a null action type a plain drive under traffic control.
     */
    public boolean driveRoute(List<String> route, TrafficControl traffic, String edgeActionType, Map<String, ?> parameters) {
        if (route.size() < 2) {
            throw new IllegalArgumentException("a route has at least two nodes, got " + route);
        }
        List<EdgeAction> each = new ArrayList<>();
        for (int i = 1; i < route.size(); i++) {
            each.add(edgeActionType == null ? null : new EdgeAction(edgeActionType, parameters));
        }
        return driveRoute(route, traffic, each);
    }

    /** An action done along one edge of a route (the ride of a lift between its landings, a guide, a door passed). */
    public record EdgeAction(String actionType, Map<String, ?> parameters) {
        public EdgeAction {
            Objects.requireNonNull(actionType, "actionType");
            parameters = Map.copyOf(parameters);
        }
    }

    /**
     * {@link #driveRoute(List, TrafficControl)} with its own action along each edge, or none (null): e.g. a route up
     * through the lift, {@code c6 -> c7 -> d1 -> d2}, riding from landing {@code c7} to landing {@code d1}, reserved as
     * the lift's cabin on the traffic map. The call succeeds once the robot arrived and every edge's action finished.
     */
    public boolean driveRoute(List<String> route, TrafficControl traffic, List<EdgeAction> edgeActionsPerEdge) {
        return driveRoute(route, traffic, edgeActionsPerEdge, false);
    }

    /**
     * {@link #driveRoute(List, TrafficControl, List)}, {@code urgent} when the robot drives to charge below its reserve:
     * traffic control then treats it like a guide (rule 3's precedence case: it does not make way, the plain robots of a
     * cycle do), master control does not ask it to make way, and after a wait over the bound it does not clear the way into
     * a room (each metre out of its way is one it may not have); refused as a deadlock it still steps aside, its way
     * forward being closed.
     */
    public boolean driveRoute(List<String> route, TrafficControl traffic, List<EdgeAction> edgeActionsPerEdge, boolean urgent) {
        if (route.size() < 2) {
            throw new IllegalArgumentException("a route has at least two nodes, got " + route);
        }
        if (edgeActionsPerEdge.size() != route.size() - 1) {
            throw new IllegalArgumentException("one edge action (or null) per edge of " + route + ", not " + edgeActionsPerEdge.size());
        }
        String call = (edgeActionsPerEdge.stream().allMatch(Objects::isNull) ? "drive "
                : edgeActionsPerEdge.stream().filter(Objects::nonNull).map(EdgeAction::actionType).distinct().collect(java.util.stream.Collectors.joining("/")) + " ")
                + String.join(" -> ", route);
        if (!ready(call)) {
            return false;
        }
        awaitAbandonedOrderEnded();
        synchronized (lock) {
            lastFailure = null;
            orderToFirstState = -1;
        }
        Optional<String> empty = batteryEmpty();
        if (empty.isPresent()) {
            // it cannot drive: lost where it stands until it is charged (rule 4: nobody waits for it, requests through its place
            // are refused at once with the reason); placing it again would have others wait for it for good
            traffic.lost(name(), empty.get());
            synchronized (lock) {
                return fail(call + " on AGV " + name() + " refused: " + empty.get());
            }
        }
        synchronized (lock) {
            this.traffic = traffic;
            drivingRoute = true;
        }
        try {
            List<Action> edgeActions = new ArrayList<>();
            for (EdgeAction a : edgeActionsPerEdge) {
                edgeActions.add(a == null ? null : action(a.actionType(), a.parameters()));
            }
            if (edgeActions.stream().allMatch(Objects::isNull)) {
                edgeActions.clear();
            }
            return driveRouteUnder(route, traffic, call, edgeActions, traffic.stepsAside(), urgent);
        } finally {
            synchronized (lock) {
                drivingRoute = false;
                if (down()) {
                    watchIdle(connectionNanos); // it went down as the call ended: the call may not have told traffic control
                }
            }
        }
    }

    /**
     * @param mayStepAside whether the robot makes way by itself (not while it is stepping aside already)
     * @param urgent       whether it drives to charge below its reserve (see {@link #driveRoute(List, TrafficControl, List, boolean)})
     */
    private boolean driveRouteUnder(List<String> route, TrafficControl traffic, String call, List<Action> edgeActions, boolean mayStepAside,
            boolean urgent) {
        awaitAbandonedOrderEnded(); // a failed drive's AGV may still roll to where it was stopped
        boolean idle;
        String at;
        AgvState last;
        synchronized (lock) {
            last = state;
        }
        if (last != null) {
            trail(last); // what it passed on its way there is reported before it asks again
        }
        synchronized (lock) {
            trailing = null;
            idle = state != null && state.nodeStates().isEmpty() && state.edgeStates().isEmpty() && !state.driving();
            at = state == null ? null : state.lastNodeId();
        }
        if (idle && at != null && !at.equals(route.get(0))) {
            // the route was planned from where the AGV stood before its last order ended elsewhere (cut short, it drove
            // on to its decision point): the map is not moved to a node the AGV is not at
            synchronized (lock) {
                return fail(call + " on AGV " + name() + " refused: the AGV stands at '" + at + "', not at the route's start '" + route.get(0) + "'");
            }
        }
        // an idle AGV at a node of its base short of its decision point (its last drive failed and it stopped before):
        // its base ends there, so it can start again instead of every later drive being refused
        boolean placed = idle ? traffic.relocate(name(), route.get(0)) : traffic.place(name(), route.get(0));
        if (!placed || !traffic.decisionPoint(name()).equals(route.get(0))) {
            synchronized (lock) {
                fail(call + " on AGV " + name() + " refused by traffic control: the robot stands at '"
                        + (traffic.read(t -> t.robots().contains(name())) ? traffic.decisionPoint(name()) : "?")
                        + "' on the traffic map, or its node has no room");
                // the map's place against the AGV's, or others queued for its node: traffic's trouble, not the robot's (three
                // such FAULTs in 6 s took a sound courier out of the service's dispatch)
                lastCause = Failure.Cause.CONGESTION;
                return false;
            }
        }
        if (mayStepAside && traffic.deadEndTaken(name(), route.get(0), route.get(1))) {
            // sent into a dead-end room another robot holds: waiting at its door would shut that robot in (its only way
            // out), so wait beside it instead, for the door and the room together (the table's dead-end rule)
            Optional<String> side = traffic.aside(name());
            if (side.isPresent()) {
                traffic.note("traffic: " + name() + " steps aside from " + route.get(0) + " to " + side.get() + ": " + route.get(1)
                        + " is a dead end that another robot holds, and " + route.get(0) + " its only way out");
                if (!driveRouteUnder(List.of(route.get(0), side.get()), traffic, "step aside " + route.get(0) + " -> " + side.get(), List.of(), false, false)) {
                    return false;
                }
                List<String> back = new ArrayList<>(route);
                back.add(0, side.get());
                List<Action> actions = new ArrayList<>(edgeActions);
                if (!actions.isEmpty()) {
                    actions.add(0, null);
                }
                return driveRouteUnder(back, traffic, call, actions, false, urgent);
            }
        }
        long sent = System.nanoTime();
        RouteDrive drive = new RouteDrive(name(), route, nextId("order"), traffic,
                (id, update, nodes, edges) -> publish(Topic.ORDER, new Order(headerIds.next(Topic.ORDER), HeaderIds.now(), Header.VERSION,
                        manufacturer, serialNumber, id, update, null, nodes, edges)),
                why -> publish(Topic.INSTANT_ACTIONS, new InstantActions(headerIds.next(Topic.INSTANT_ACTIONS), HeaderIds.now(), Header.VERSION,
                        manufacturer, serialNumber, List.of(action("startPause", Map.of())))), edgeActions, urgent);
        screen.sent(drive.orderId()); // its states are progress of our order, not of a stranger's
        Optional<String> refused = drive.start();
        if (refused.isPresent()) {
            if (drive.endedAtDecisionPoint()) {
                // its first stretch was sent: it drives to the decision point, and what it passes there is reported; the next
                // order waits until it has ended there (once the AGV has taken it: a state of its last order says nothing)
                await(() -> state != null && drive.orderId().equals(state.orderId()), timeouts.stateSeconds());
                AgvState now;
                synchronized (lock) {
                    abandonedOrder = drive.orderId();
                    trailing = drive;
                    now = state;
                }
                if (now != null) {
                    trail(now);
                }
            } else {
                traffic.stopAt(name(), route.get(0));
            }
            synchronized (lock) {
                fail(call + " on AGV " + name() + " refused by traffic control: " + refused.get());
                if (drive.deadlockAvoided()) {
                    lastCause = Failure.Cause.CONGESTION;
                }
            }
            if (mayStepAside) {
                stepAsideAfter(drive, traffic, urgent);
            }
            return false;
        }
        boolean ok = awaitOutcome(call, sent, s -> {
            RouteDrive.Verdict v;
            try {
                v = drive.onState(s);
            } catch (IllegalStateException | IllegalArgumentException inconsistent) {
                // the AGV reports what the table cannot place (e.g. a node off the route): a failure with its reason, not a crash
                v = new RouteDrive.Verdict(false, "traffic control: " + inconsistent.getMessage());
            }
            return v.done() ? Outcome.DONE : v.failure() != null ? new Outcome(false, v.failure(), v.congestion()) : Outcome.PENDING;
        }, drive.orderId(), true);
        if (!ok) {
            boolean down;
            synchronized (lock) {
                down = connection == ConnectionState.CONNECTIONBROKEN || connection == ConnectionState.OFFLINE;
            }
            drive.abandon(down);
            AgvState now;
            synchronized (lock) {
                abandonedOrder = drive.orderId(); // it may still drive to its decision point: the next order waits for that
                trailing = down ? null : drive;
                now = state;
            }
            if (now != null) {
                trail(now);
            }
            Optional<String> empty = batteryEmpty();
            if (empty.isPresent() && !down) {
                // ran flat on the way: lost where it stopped (its base ahead freed) until it is charged, not waited for
                traffic.lost(name(), empty.get());
                synchronized (lock) {
                    lastFailure = lastFailure + "; " + empty.get() + ", lost on the traffic map till then";
                }
                return false;
            }
            if ((mayStepAside || drive.madeWay()) && !down) {
                stepAsideAfter(drive, traffic, urgent);
            }
        }
        return ok;
    }

    /**
     * Refused as a deadlock (the robot would have waited for robots that wait for it): out of their way to a free
     * neighbouring stop node, once it stands at its decision point, so that they can pass; the call's failure says where
     * it went, and its caller re-plans from there.
     */
    private void stepAsideAfter(RouteDrive drive, TrafficControl traffic, boolean urgent) {
        if (drive.waitedInVain()) {
            if (!urgent) { // an urgent robot keeps its place on its way to charge: its caller asks again from there
                clearTheWay(traffic);
            }
            return;
        }
        if (!drive.madeWay() && drive.refusal().map(r -> r.cycle().isEmpty()).orElse(true)) {
            return;
        }
        FailedCall failed = failedCallOnceStopped();
        String why = failed.why();
        Failure.Cause cause = failed.cause();
        String from = traffic.decisionPoint(name());
        List<String> cycle = drive.refusal().map(r -> r.cycle()).orElseGet(() -> traffic.madeWayFor(name()));
        Optional<String> side = traffic.wayOut(name(), cycle);
        if (side.isEmpty()) {
            // nowhere to go: one of the robots it would have waited for makes way instead
            Optional<String> other = drive.refusal().flatMap(r -> traffic.askToMakeWay(name(), r.cycle()));
            synchronized (lock) {
                lastFailure = why + other.map(o -> "; nowhere to step aside to, so " + o + " makes way").orElse("");
                lastCause = cause;
            }
            return;
        }
        traffic.note("traffic: " + name() + " steps aside from " + from + " to " + side.get() + ", out of the way of "
                + drive.refusal().map(r -> r.cycle().toString()).orElse("a robot refused as a deadlock"));
        List<String> aside = traffic.asideRoute(from, side.get());
        boolean moved = driveRouteUnder(aside, traffic, "step aside " + String.join(" -> ", aside), List.of(), false, false);
        // could not get out of the way: one of the robots it would have waited for makes way instead, as when it had nowhere to go
        Optional<String> other = moved ? Optional.empty() : drive.refusal().flatMap(r -> traffic.askToMakeWay(name(), r.cycle()));
        synchronized (lock) {
            lastFailure = why + (moved ? "; stepped aside to '" + side.get() + "', out of the others' way" : "; could not step aside: " + lastFailure
                    + other.map(o -> "; so " + o + " makes way").orElse(""));
            lastCause = cause; // the drive's end is what the call failed of; stepping aside is how it got out of the way
        }
    }

    /**
     * Its wait went over the bound: into a free room off the corridor node it stands at, if there is one
     * ({@link TrafficControl#roomAside}), so that the robots queued behind it move on while its caller re-plans; the
     * call's failure says where it went. Standing there, it was the end of a chain of waits until its next drive.
     */
    private void clearTheWay(TrafficControl traffic) {
        FailedCall failed = failedCallOnceStopped();
        String why = failed.why();
        Failure.Cause cause = failed.cause();
        String from = traffic.decisionPoint(name());
        Optional<String> room = traffic.roomAside(name());
        if (room.isEmpty()) {
            return;
        }
        traffic.note("traffic: " + name() + " steps aside from " + from + " to " + room.get() + ", clearing the way after a wait over the bound");
        boolean moved = driveRouteUnder(List.of(from, room.get()), traffic, "step aside " + from + " -> " + room.get(), List.of(), false, false);
        synchronized (lock) {
            lastFailure = why + (moved ? "; stepped aside to '" + room.get() + "', clearing the way" : "; could not step aside: " + lastFailure);
            lastCause = cause;
        }
    }

    /** The call's failure as it stands, and why: a step aside after it keeps it, saying only where the robot went. */
    private record FailedCall(String why, Failure.Cause cause) {
    }

    /** The call's failure, taken once the abandoned order has ended (the AGV stands at its decision point). */
    private FailedCall failedCallOnceStopped() {
        FailedCall failed;
        synchronized (lock) {
            failed = new FailedCall(lastFailure, lastCause);
        }
        awaitAbandonedOrderEnded();
        return failed;
    }

    private boolean runOrder(String orderId, List<Node> nodes, List<Edge> edges, List<Action> actions, String call) {
        if (!ready(call)) {
            return false;
        }
        awaitAbandonedOrderEnded();
        long sent = System.nanoTime();
        synchronized (lock) {
            orderToFirstState = -1;
        }
        screen.sent(orderId);
        publish(Topic.ORDER, new Order(headerIds.next(Topic.ORDER), HeaderIds.now(), Header.VERSION, manufacturer, serialNumber, orderId, 0,
                null, nodes, edges));
        return awaitOutcome(call, sent, s -> {
            if (!orderId.equals(s.orderId())) {
                return Outcome.PENDING;
            }
            for (AgvError e : s.errors()) {
                if (orderId.equals(e.reference("orderId"))) {
                    return Outcome.failed(e.describe());
                }
            }
            for (Action a : actions) {
                Optional<ActionState> as = s.actionState(a.actionId());
                if (as.isPresent() && as.get().actionStatus() == ActionStatus.FAILED) {
                    return Outcome.failed(a.actionType() + " failed" + result(as.get()));
                }
            }
            boolean actionsDone = actions.stream()
                    .allMatch(a -> s.actionState(a.actionId()).map(as -> as.actionStatus() == ActionStatus.FINISHED).orElse(false));
            return s.nodeStates().isEmpty() && s.edgeStates().isEmpty() && !s.driving() && actionsDone ? Outcome.DONE : Outcome.PENDING;
        }, orderId);
    }

    /**
     * An AGV refuses a new order while it still runs one (VDA 5050 has no queue of orders), and the
     * order given up on goes on after a broken connection, or up to its next node after a cancel: so
     * the next order waits until the AGV reports it ended, at most an action's time, less if the AGV
     * falls silent. Without this the re-plans after such a failure were refused at once, one after
     * the other, and the task aborted while the robot was fine.
     */
    private void awaitAbandonedOrderEnded() {
        synchronized (lock) {
            if (abandonedOrder == null) {
                return;
            }
        }
        // silent: no state for stateSeconds since the wait began (or since its last state or (re)connection, if later);
        // a frozen AGV is not waited for, but one that was only slow (a loaded machine) gets that long to speak again
        long began = System.nanoTime();
        await(() -> abandonedOrderEnded()
                || System.nanoTime() - Math.max(began, Math.max(stateNanos, connectionNanos)) > seconds(timeouts.stateSeconds()), timeouts.actionSeconds());
        synchronized (lock) {
            // kept until the AGV shows it ended: the next order after a refusal ("still executing") waits again
            if (abandonedOrderEnded()) {
                abandonedOrder = null;
            }
        }
    }

    /** Whether the AGV's state shows the abandoned order ended (or another order running); call with the lock held. */
    private boolean abandonedOrderEnded() {
        return state == null || !abandonedOrder.equals(state.orderId())
                || state.nodeStates().isEmpty() && state.edgeStates().isEmpty() && !state.driving();
    }

    /** Whether the AGV is (or comes) online; otherwise records why not. */
    private boolean ready(String call) {
        if (!awaitOnline()) {
            synchronized (lock) {
                if (down()) {
                    fail("AGV " + name() + " is " + connection + ", cannot " + call);
                } else {
                    fail(String.format(Locale.ROOT, "AGV %s did not come online on %s within %.1f s, cannot %s", name(), link.broker(),
                            timeouts.onlineSeconds(), call));
                }
            }
            return false;
        }
        return true;
    }

    private record Outcome(boolean done, String failure, boolean congestion) {
        static final Outcome PENDING = new Outcome(false, null, false);
        static final Outcome DONE = new Outcome(true, null, false);

        static Outcome failed(String why) {
            return new Outcome(false, why, false);
        }
    }

    /** Waits for the verdict on the AGV's states; also catches rejections (errors naming an order it did not take), silence and broken connections. */
    private boolean awaitOutcome(String call, long sentNanos, Function<AgvState, Outcome> verdict, String orderId) {
        return awaitOutcome(call, sentNanos, verdict, orderId, false);
    }

    /** @param anyState whether the verdict also sees states older than the call (traffic decisions do not wait for the AGV) */
    private boolean awaitOutcome(String call, long sentNanos, Function<AgvState, Outcome> verdict, String orderId, boolean anyState) {
        long deadline = sentNanos + seconds(timeouts.actionSeconds());
        synchronized (lock) {
            lastFailure = null;
            while (true) {
                long now = System.nanoTime();
                if (state != null && (anyState || stateNanos >= sentNanos)) {
                    if (orderId != null && orderToFirstState < 0 && orderId.equals(state.orderId())) {
                        orderToFirstState = stateNanos - sentNanos;
                    }
                    if (orderId != null && !orderId.equals(state.orderId())) {
                        for (AgvError e : state.errors()) {
                            if (orderId.equals(e.reference("orderId"))) {
                                return fail(call + " rejected by AGV " + name() + ": " + e.describe());
                            }
                        }
                    }
                    Outcome o = verdict.apply(state);
                    if (o.done()) {
                        return true;
                    }
                    if (o.failure() != null) {
                        fail(call + " failed on AGV " + name() + ": " + o.failure());
                        if (o.congestion()) {
                            lastCause = Failure.Cause.CONGESTION;
                        }
                        return false;
                    }
                }
                // the grace runs while this master is connected itself: after a broker restart the AGV's ONLINE comes after ours
                if (down() && connectionNanos >= sentNanos
                        && link.isConnected() && now - Math.max(connectionNanos, masterReconnectNanos) > seconds(timeouts.reconnectGraceSeconds())) {
                    if (orderId != null) {
                        abandonedOrder = orderId;
                    }
                    return fail(String.format(Locale.ROOT, "AGV %s reported %s%s during %s and did not come back within %.1f s", name(), connection,
                            connection == ConnectionState.CONNECTIONBROKEN ? " (its last will)" : "", call, timeouts.reconnectGraceSeconds()));
                }
                long heard = Math.max(Math.max(stateNanos, sentNanos), masterReconnectNanos);
                if (link.isConnected() && now - heard > seconds(timeouts.stateSeconds())) {
                    return giveUp(orderId, String.format(Locale.ROOT, "no state from AGV %s for %.1f s during %s (timeout)", name(), timeouts.stateSeconds(),
                            call));
                }
                if (now > deadline) {
                    return giveUp(orderId, String.format(Locale.ROOT, "%s on AGV %s did not finish within %.1f s (timeout)", call, name(),
                            timeouts.actionSeconds()));
                }
                try {
                    lock.wait(50);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return fail(call + " on AGV " + name() + " interrupted");
                }
            }
        }
    }

    /**
     * Why the AGV cannot drive for want of charge, if its state says so: its battery at 0 % and not charging (VDA 5050's
     * {@code batteryState}), where it stands.
     */
    private Optional<String> batteryEmpty() {
        synchronized (lock) {
            if (state == null || state.batteryState() == null || state.batteryState().charging() || state.batteryState().batteryCharge() > 0) {
                return Optional.empty();
            }
            return Optional.of("its battery is empty (batteryCharge 0 %) at " + state.lastNodeId() + ": it cannot drive until it is charged");
        }
    }

    private boolean fail(String why) {
        lastFailure = why;
        lastCause = Failure.Cause.FAULT;
        return false;
    }

    /** Master control gave up on an order the AGV may still be executing (silence, timeout): it should stop it. */
    private boolean giveUp(String orderId, String why) {
        if (orderId != null) {
            abandonedOrder = orderId;
            Action cancel = action("cancelOrder", Map.of());
            publish(Topic.INSTANT_ACTIONS, new InstantActions(headerIds.next(Topic.INSTANT_ACTIONS), HeaderIds.now(), Header.VERSION,
                    manufacturer, serialNumber, List.of(cancel)));
        }
        return fail(why);
    }

    private boolean await(BooleanSupplier condition, double seconds) {
        long deadline = System.nanoTime() + seconds(seconds);
        synchronized (lock) {
            while (!condition.getAsBoolean()) {
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    return false;
                }
                try {
                    lock.wait(Math.max(1, Math.min(50, left / 1_000_000)));
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return false;
                }
            }
            return true;
        }
    }

    void receive(Received r) {
        Header h;
        switch (r.address().topic()) {
            case STATE -> h = r.as(AgvState.class);
            case CONNECTION -> h = r.as(Connection.class);
            case FACTSHEET -> {
                synchronized (lock) {
                    factsheet = r.json();
                    lock.notifyAll();
                }
                return;
            }
            default -> {
                return;
            }
        }
        if (h instanceof AgvState s) {
            synchronized (lock) {
                // a duplicate (QoS 1) or an older state overtaken by a newer one; a restarted AGV says ONLINE first
                if (!screen.accept(s)) {
                    return;
                }
                state = s;
                stateNanos = System.nanoTime();
                lock.notifyAll();
            }
            trail(s); // outside the lock: traffic control has its own
            return;
        }
        synchronized (lock) {
            if (h instanceof Connection c) {
                connection = c.connectionState();
                connectionNanos = System.nanoTime();
                if (connection == ConnectionState.ONLINE) {
                    screen.reset();
                } else if (traffic != null && !drivingRoute) {
                    watchIdle(connectionNanos);
                }
            }
            lock.notifyAll();
        }
    }

    /** Reports the nodes the AGV passes on its way to the decision point of a drive whose call ended there (see {@link RouteDrive#trail}). */
    private void trail(AgvState s) {
        RouteDrive t;
        synchronized (lock) {
            t = trailing;
        }
        if (t != null && t.trail(s)) {
            synchronized (lock) {
                if (trailing == t) {
                    trailing = null;
                }
            }
        }
    }

    /**
     * An AGV standing on the traffic map without a route running reported its last will (or OFFLINE): if it is
     * still down one reconnect grace later, traffic control is told it is lost where it stands, so its base
     * is freed and nobody is driven into it. Call with the lock held.
     */
    private void watchIdle(long since) {
        if (traffic == null) {
            return;
        }
        TrafficControl watched = traffic;
        IDLE_WATCH.schedule(() -> {
            String why;
            synchronized (lock) {
                // the same last will, still unanswered by a state, no route running, and this master connected to see it
                if (connectionNanos != since || !down() || drivingRoute || !link.isConnected()
                        || System.nanoTime() - Math.max(connectionNanos, masterReconnectNanos) < seconds(timeouts.reconnectGraceSeconds())) {
                    if (connectionNanos == since && down() && !drivingRoute) {
                        watchIdle(since); // the master itself reconnected meanwhile: its grace starts again
                    }
                    return;
                }
                why = String.format(Locale.ROOT, "%s%s while idle, not back within the reconnect grace of %.1f s", connection,
                        connection == ConnectionState.CONNECTIONBROKEN ? " (its last will)" : "", timeouts.reconnectGraceSeconds());
            }
            watched.lost(name(), why);
        }, seconds(timeouts.reconnectGraceSeconds()) + 50_000_000L, TimeUnit.NANOSECONDS);
    }

    void masterReconnected() {
        synchronized (lock) {
            masterReconnectNanos = System.nanoTime();
            lock.notifyAll();
        }
    }

    private void publish(Topic topic, Object message) {
        link.publish(topic.of(manufacturer, serialNumber), message, false);
    }

    private static Action action(String actionType, Map<String, ?> parameters) {
        List<ActionParameter> ps = new ArrayList<>();
        new LinkedHashMap<>(parameters).forEach((k, v) -> ps.add(new ActionParameter(k, v)));
        return new Action(actionType, nextId(actionType), null, BlockingType.HARD, ps.isEmpty() ? null : ps);
    }

    private static String nextId(String kind) {
        return "triad-" + SESSION + "-" + kind + "-" + IDS.incrementAndGet();
    }

    private static String describeCall(String what, String at, String to) {
        return what + (to == null ? " at " + at : " " + at + " -> " + to);
    }

    private static String result(ActionState as) {
        return as.resultDescription() == null ? "" : ": " + as.resultDescription();
    }

    private static long seconds(double s) {
        return (long) (s * 1e9);
    }
}
