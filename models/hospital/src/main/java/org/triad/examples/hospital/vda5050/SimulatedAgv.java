package org.triad.examples.hospital.vda5050;

import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.Deque;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

import org.triad.examples.hospital.HospitalFloor;
import org.triad.examples.hospital.HospitalObjects;
import org.triad.examples.hospital.HospitalBuilding;
import org.triad.examples.hospital.LobbyParking;
import org.triad.sim.Robot;
import org.triad.sim.Simulation;
import org.triad.sim.SimulationClock;
import org.triad.sim.TracePicture;
import org.triad.sim.Vec2;
import org.triad.vda5050.master.MasterControl;
import org.triad.vda5050.mqtt.MqttLink;
import org.triad.vda5050.mqtt.Received;
import org.triad.vda5050.protocol.AgvState;
import org.triad.vda5050.protocol.Connection;
import org.triad.vda5050.protocol.Header;
import org.triad.vda5050.protocol.HeaderIds;
import org.triad.vda5050.protocol.InstantActions;
import org.triad.vda5050.protocol.Messages.Action;
import org.triad.vda5050.protocol.Messages.ActionState;
import org.triad.vda5050.protocol.Messages.ActionStatus;
import org.triad.vda5050.protocol.Messages.AgvError;
import org.triad.vda5050.protocol.Messages.AgvPosition;
import org.triad.vda5050.protocol.Messages.BatteryState;
import org.triad.vda5050.protocol.Messages.ConnectionState;
import org.triad.vda5050.protocol.Messages.Edge;
import org.triad.vda5050.protocol.Messages.EdgeState;
import org.triad.vda5050.protocol.Messages.ErrorLevel;
import org.triad.vda5050.protocol.Messages.Information;
import org.triad.vda5050.protocol.Messages.Load;
import org.triad.vda5050.protocol.Messages.Node;
import org.triad.vda5050.protocol.Messages.NodeState;
import org.triad.vda5050.protocol.Messages.Reference;
import org.triad.vda5050.protocol.Messages.SafetyState;
import org.triad.vda5050.protocol.Messages.Velocity;
import org.triad.vda5050.protocol.Order;
import org.triad.vda5050.protocol.Topic;
import org.triad.vda5050.protocol.Visualization;

import generated.hospital.domain.WayPoint;

/**
 * A simulated courier of the dyn4j hospital as a VDA 5050 AGV on a broker. It publishes {@code connection}
 * (ONLINE, OFFLINE on a clean stop, CONNECTIONBROKEN as its last will), {@code state} on every change and at
 * least every second, {@code visualization} and {@code factsheet}; it executes {@code order}s (nodes are the
 * models' waypoints; an edge drives the model edge, or guides or accompanies a person with an edge action
 * {@code guide}/{@code walk}; node actions {@code pick}/{@code drop} with {@code loadId} and
 * {@code startFollowing} with {@code personId}), order updates, and {@code instantActions} (cancelOrder,
 * startPause/stopPause, factsheetRequest, stateRequest). What the simulator reports as a failure (a closed
 * door, a blocked corridor) becomes an error in the state, with the simulator's reason.
 *
 * <p>The AGV is one courier of a {@link HospitalBuilding}, whose clock steps one simulation for all its couriers
 * ({@code speed} times faster than the wall clock, so that a state message shows the robot on its way). Messages
 * reach the AGV's own thread through a queue; it handles them, and drives, under the clock's lock (see
 * {@link SimulationClock}), and while its robot drives it handles the messages that arrive meanwhile.
 */
public final class SimulatedAgv implements AutoCloseable {
    /** Floor 0's map (the lobby's, where every courier starts): a position's {@code mapId} is its floor's, {@link #mapId(int)}. */
    public static final String MAP_ID = "hospital-0";

    /** The VDA 5050 map id of a floor of the hospital ({@code hospital-0}, {@code hospital-1}): one map per floor, as VDA 5050 has it. */
    public static String mapId(int floor) {
        return "hospital-" + floor;
    }
    private final String broker;
    private final String serial;
    private final double speed;
    private final Consumer<String> log;
    private final HospitalBuilding hospital;
    /** Whether this AGV made its building (and starts and stops its clock) or shares one. */
    private final boolean ownsBuilding;
    private final HospitalBuilding.Courier courier;
    private final HospitalFloor floor;
    private final HospitalObjects objects;
    private final Simulation sim;
    private final Robot robot;
    private final Path pictures;
    private final HeaderIds headerIds = new HeaderIds();
    private final LinkedBlockingQueue<Received> inbox = new LinkedBlockingQueue<>();
    private final Thread thread;
    private final java.util.concurrent.ExecutorService sender;
    private volatile boolean running = true;
    private MqttLink link;

    // AGV state, owned by the AGV thread
    private String orderId = "";
    private int orderUpdateId;
    private String lastNodeId;
    private int lastNodeSequenceId;
    private final List<Node> pendingNodes = new ArrayList<>();
    private final Deque<Edge> pendingEdges = new ArrayDeque<>();
    private final Map<String, ActionState> actionStates = new LinkedHashMap<>();
    private final List<AgvError> errors = new ArrayList<>();
    private final Set<String> seenOrders = new HashSet<>();
    private boolean driving;
    /** A new order's first node is where the AGV stands: reached at once, its actions run first. */
    private boolean atOrderStart;
    /** A faulty AGV (fault injection): drives onto its horizon as if it were released. */
    private volatile boolean ignoresBase;
    private boolean cancelRequested;
    private String cancelActionId;
    private long lastStateNanos;
    private long lastVisualizationNanos;
    private long statesSent;

    /**
     * An AGV alone in a hospital of its own (its clock starts with {@link #start()} and stops with {@link #close()}).
     *
     * @param speed    virtual seconds per wall-clock second (1 = real time), or {@link SimulationClock#AS_FAST_AS_POSSIBLE}
     * @param pictures a folder to draw {@code <serial>.png} into after every order, or null
     * @param log      where one-line reports go (orders received, rejected, finished)
     */
    public SimulatedAgv(String broker, String serial, long seed, double speed, Path pictures, Consumer<String> log) {
        this(broker, new HospitalBuilding(seed, true, List.of(Objects.requireNonNull(serial, "serial"))), serial, speed, true, pictures, log);
    }

    /**
     * The courier {@code serial} of a shared building as an AGV; it reports state and drives once the building's owner
     * has started the clock.
     *
     * @param pictures a folder to draw {@code <serial>.png} (the whole building) into after every order, or null
     * @throws IllegalArgumentException if the building has no courier {@code serial}
     */
    public SimulatedAgv(String broker, HospitalBuilding building, String serial, Path pictures, Consumer<String> log) {
        this(broker, building, serial, 1, false, pictures, log);
    }

    private SimulatedAgv(String broker, HospitalBuilding building, String serial, double speed, boolean ownsBuilding, Path pictures,
            Consumer<String> log) {
        this.broker = Objects.requireNonNull(broker, "broker");
        this.serial = Objects.requireNonNull(serial, "serial");
        if (!(speed > 0)) {
            throw new IllegalArgumentException("speed is a positive factor, not " + speed);
        }
        Topic.STATE.of(MasterControl.TRIAD, serial);
        this.speed = speed;
        this.pictures = pictures;
        this.log = Objects.requireNonNull(log, "log");
        this.hospital = building;
        this.ownsBuilding = ownsBuilding;
        this.courier = building.courier(serial);
        this.floor = hospital.floor();
        this.objects = hospital.objects();
        this.sim = hospital.sim();
        this.robot = courier.robot();
        this.lastNodeId = nodeHere();
        this.thread = new Thread(this::loop, "agv-" + serial);
        this.sender = java.util.concurrent.Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "agv-" + serial + "-send");
            t.setDaemon(true);
            return t;
        });
    }

    /**
     * The simulated hospital of this AGV (to script faults before {@link #start()}:
     * {@code hospital().sim().at(40).closeDoor(...)}; once it runs, through {@code hospital().clock()}).
     */
    public HospitalBuilding hospital() {
        return hospital;
    }

    public String serial() {
        return serial;
    }

    /**
     * Connects (last will CONNECTIONBROKEN), reports ONLINE, its factsheet and state, and starts executing.
     *
     * @throws org.triad.vda5050.mqtt.BrokerUnreachableException when no broker answers
     */
    public SimulatedAgv start() {
        Connection will = new Connection(0, HeaderIds.now(), Header.VERSION, MasterControl.TRIAD, serial,
                ConnectionState.CONNECTIONBROKEN);
        link = MqttLink.connect(broker, serial, "triad-agv-" + serial, new MqttLink.Will(topic(Topic.CONNECTION), will), log, 5, 5);
        link.subscribe(topic(Topic.ORDER), inbox::add);
        link.subscribe(topic(Topic.INSTANT_ACTIONS), inbox::add);
        link.onReconnect(this::announce);
        announce();
        if (ownsBuilding) {
            hospital.start(speed);
        }
        thread.start();
        return this;
    }

    /**
     * Makes this AGV faulty: it drives its orders' horizon as if it were released, beyond where master control
     * allowed it (a rogue AGV, for the traffic tests). Call before {@link #start()}.
     */
    public SimulatedAgv ignoringBase() {
        ignoresBase = true;
        return this;
    }

    /** State messages published so far. */
    public long statesSent() {
        return statesSent;
    }

    private void announce() {
        send(Topic.CONNECTION, new Connection(headerIds.next(Topic.CONNECTION), HeaderIds.now(), Header.VERSION,
                MasterControl.TRIAD, serial, ConnectionState.ONLINE), true);
        send(Topic.FACTSHEET, HospitalFactsheet.of(serial, headerIds.next(Topic.FACTSHEET)), true);
        lastStateNanos = 0;
    }

    /**
     * Publishes in order on the AGV's sender thread: building a message needs the clock's lock (it reads the
     * simulation), sending it (schema check, MQTT) does not, and must not hold up the building's other robots.
     */
    private void send(Topic t, Object message, boolean retained) {
        try {
            sender.execute(() -> {
                try {
                    link.publish(topic(t), message, retained);
                } catch (RuntimeException e) {
                    log.accept("agv " + serial + ": " + e.getMessage());
                }
            });
        } catch (java.util.concurrent.RejectedExecutionException closed) {
            // closing: nothing more goes out after OFFLINE
        }
    }

    private String topic(Topic t) {
        return t.of(MasterControl.TRIAD, serial);
    }

    // ---- the AGV thread ------------------------------------------------------------------------

    private void loop() {
        // the owner of a shared building may start its clock after starting its AGVs
        SimulationClock clock;
        while ((clock = hospital.clock().orElse(null)) == null) {
            try {
                Thread.sleep(20);
            } catch (InterruptedException e) {
                return;
            }
        }
        clock.whileWaiting(this::whileDriving);
        clock.run(s -> publishState());
        while (running) {
            try {
                Received r = inbox.poll(100, TimeUnit.MILLISECONDS);
                if (r == null && pendingEdges.isEmpty() && pendingNodes.isEmpty() && !stateDue()) {
                    continue; // nothing to do: leave the clock's lock to those who have
                }
                clock.run(s -> {
                    if (r != null) {
                        handle(r, false);
                    }
                    if (!pendingEdges.isEmpty() || !pendingNodes.isEmpty()) {
                        executeOrder();
                    }
                    stateIfDue();
                });
            } catch (InterruptedException e) {
                return;
            } catch (RuntimeException e) {
                if (!running) {
                    return;
                }
                log.accept("agv " + serial + ": " + e);
                error("internalError", e.toString(), List.of());
                publishState();
            }
        }
    }

    /** Handles a message; {@code busy} while an order runs (new orders are then rejected, updates appended). */
    private void handle(Received r, boolean busy) {
        if (r.address().topic() == Topic.ORDER) {
            if (!busy) {
                carriedByLift();
            }
            receiveOrder(r.as(Order.class), busy);
        } else if (r.address().topic() == Topic.INSTANT_ACTIONS) {
            for (Action a : r.as(InstantActions.class).actions()) {
                instantAction(a);
            }
        }
        publishState();
    }

    private void receiveOrder(Order o, boolean busy) {
        if (o.orderId().equals(orderId) && o.orderUpdateId() == orderUpdateId || seenOrders.contains(o.orderId()) && !o.orderId().equals(orderId)) {
            log.accept("agv " + serial + ": ignored duplicate order " + o.orderId() + "/" + o.orderUpdateId());
            return;
        }
        List<Node> nodes = o.nodes().stream().sorted(Comparator.comparingInt(Node::sequenceId)).toList();
        List<Edge> edges = o.edges().stream().sorted(Comparator.comparingInt(Edge::sequenceId)).toList();
        boolean update = o.orderId().equals(orderId);
        Optional<String> invalid = invalid(o, nodes, edges, update, busy);
        if (invalid.isPresent()) {
            String[] typeAndWhy = invalid.get().split(": ", 2);
            log.accept("agv " + serial + ": rejected order " + o.orderId() + "/" + o.orderUpdateId() + ": " + invalid.get());
            error(typeAndWhy[0], typeAndWhy[1], List.of(new Reference("orderId", o.orderId()),
                    new Reference("orderUpdateId", Integer.toString(o.orderUpdateId()))));
            return;
        }
        log.accept("agv " + serial + ": accepted order " + o.orderId() + "/" + o.orderUpdateId() + " " + describe(nodes, edges));
        seenOrders.add(o.orderId());
        if (!update) {
            actionStates.clear();
            errors.clear();
            pendingNodes.clear();
            pendingEdges.clear();
            cancelRequested = false;
        }
        if (update) {
            // an update replaces the horizon; the base it stitches onto stays
            pendingNodes.removeIf(n -> !n.released());
            pendingEdges.removeIf(e -> !e.released());
        }
        orderId = o.orderId();
        orderUpdateId = o.orderUpdateId();
        for (Node n : nodes) {
            n.actions().forEach(a -> actionStates.put(a.actionId(), waiting(a)));
        }
        for (Edge e : edges) {
            e.actions().forEach(a -> actionStates.put(a.actionId(), waiting(a)));
        }
        // a new order's first node is where the AGV stands: reached at once, its actions run first;
        // an update's first node is the decision point it stitches onto, already known
        if (!update) {
            lastNodeSequenceId = nodes.get(0).sequenceId();
            atOrderStart = true;
            pendingNodes.addAll(nodes);
        } else {
            pendingNodes.addAll(nodes.subList(1, nodes.size()));
        }
        pendingEdges.addAll(edges);
    }

    private Optional<String> invalid(Order o, List<Node> nodes, List<Edge> edges, boolean update, boolean busy) {
        if (update && o.orderUpdateId() < orderUpdateId) {
            return Optional.of("orderUpdateError: update " + o.orderUpdateId() + " of order " + o.orderId() + " is older than " + orderUpdateId);
        }
        if (!update && (busy || !pendingEdges.isEmpty())) {
            return Optional.of("orderError: still executing order " + orderId + "; cancel it first");
        }
        if (nodes.isEmpty() || edges.size() != nodes.size() - 1) {
            return Optional.of("validationError: an order needs n nodes joined by n-1 edges, got " + nodes.size() + " and " + edges.size());
        }
        for (Node n : nodes) {
            if (!floor.modelWaypoints().contains(n.nodeId()) && !LobbyParking.isPlace(n.nodeId())) {
                return Optional.of("validationError: node '" + n.nodeId() + "' is not on the hospital map " + floor.modelWaypoints());
            }
            for (Action a : n.actions()) {
                if (!List.of("pick", "drop", "startFollowing", "startCharging").contains(a.actionType())) {
                    return Optional.of("validationError: node action '" + a.actionType() + "' is not supported (pick, drop, startFollowing, startCharging)");
                }
            }
        }
        for (int i = 0; i < edges.size(); i++) {
            Edge e = edges.get(i);
            if (!e.startNodeId().equals(nodes.get(i).nodeId()) || !e.endNodeId().equals(nodes.get(i + 1).nodeId())) {
                return Optional.of("validationError: edge '" + e.edgeId() + "' does not join nodes " + nodes.get(i).nodeId() + " and "
                        + nodes.get(i + 1).nodeId());
            }
            boolean ride = e.actions().stream().anyMatch(a -> a.actionType().equals("ride"));
            if (floor.route(e.startNodeId(), e.endNodeId()).isEmpty() && !ride) {
                return Optional.of("noRouteError: no corridor from " + e.startNodeId() + " to " + e.endNodeId());
            }
            for (Action a : e.actions()) {
                if (!List.of("guide", "walk", "passDoor", "ride").contains(a.actionType())) {
                    return Optional.of("validationError: edge action '" + a.actionType() + "' is not supported (guide, walk, passDoor, ride)");
                }
            }
        }
        if (update && !nodes.get(0).actions().isEmpty()) {
            return Optional.of("validationError: an update of a running order cannot add actions to its first node");
        }
        List<Node> base = pendingNodes.stream().filter(Node::released).toList();
        String start = update && !base.isEmpty() ? base.get(base.size() - 1).nodeId() : lastNodeId;
        // an order for the models' lobby starts where the AGV stands in it, on a parking spot or the dock: a master that
        // knows the lobby as one waypoint (./triad run, a plain drive) drives it from there as before
        if (!nodes.get(0).nodeId().equals(start) && (update || !LobbyParking.waypointOf(start).equals(nodes.get(0).nodeId()))) {
            return Optional.of("noRouteError: the order starts at " + nodes.get(0).nodeId() + " but the AGV is at " + start);
        }
        return Optional.empty();
    }

    private void executeOrder() {
        String order = orderId;
        // a new order's first node has been reached: run its actions, then drive each released edge and run its end node's actions
        if (atOrderStart) {
            atOrderStart = false;
            Node at = pendingNodes.remove(0);
            boolean ok = nodeActions(at);
            if (LobbyParking.HALL.equals(LobbyParking.waypointOf(lastNodeId)) && !at.actions().isEmpty()) {
                lastNodeId = nodeHere(); // a charge asked for at the lobby drives onto the dock: it stands there now
            }
            if (!ok) {
                abortOrder("node action failed");
                return;
            }
        }
        while (!pendingEdges.isEmpty()) {
            if (cancelRequested) {
                abortOrder("cancelled");
                finishCancel();
                return;
            }
            Edge e = pendingEdges.peekFirst();
            if (!e.released() && !ignoresBase) {
                return; // the decision point: stop here until master control extends the base
            }
            Node end = pendingNodes.get(0);
            driving = true;
            e.actions().forEach(a -> setStatus(a, ActionStatus.RUNNING, null));
            publishState();
            boolean ok = traverse(e);
            driving = false;
            if (!ok) {
                String why = courier.log().lastFailure().orElse("failed");
                e.actions().forEach(a -> setStatus(a, ActionStatus.FAILED, why));
                String[] typeAndWhy = why.split(": ", 2);
                error(typeAndWhy[0], typeAndWhy.length > 1 ? typeAndWhy[1] : why, List.of(new Reference("orderId", order),
                        new Reference("edgeId", e.edgeId())));
                log.accept("agv " + serial + ": edge " + e.edgeId() + " of order " + order + " failed: " + why);
                // stopped on the way by a robot or a person (blocked, timed out): a plain drive backs to the edge's start
                // node, so that the AGV stands on a node of its order again (master control keeps the edge for it until it
                // reports that node); otherwise (in front of a closed door, where it sees it open again; the lift; a guide;
                // the way back blocked too) it reports the node it stands at, so the next plan starts there
                boolean blocked = why.startsWith("PATH_BLOCKED") || why.startsWith("TIMEOUT");
                lastNodeId = e.actions().isEmpty() && blocked && backOff(e) ? e.startNodeId() : nodeHere();
                abortOrder("edge " + e.edgeId() + " failed");
                return;
            }
            e.actions().forEach(a -> setStatus(a, ActionStatus.FINISHED, null));
            pendingEdges.removeFirst();
            pendingNodes.remove(0);
            lastNodeId = end.nodeId();
            lastNodeSequenceId = end.sequenceId();
            publishState();
            if (!nodeActions(end)) {
                abortOrder("node action failed");
                return;
            }
        }
        if (cancelRequested) {
            finishCancel();
        }
        log.accept(String.format(Locale.ROOT, "agv %s: order %s finished at %s (%.1f s virtual time)", serial, order, lastNodeId, sim.time()));
        publishState();
        drawPicture();
    }

    /**
     * A lift carried the AGV standing in one cabin to the cabin of another floor (the building moved it, not an order):
     * its last node is now the cabin it stands in, so the next order starts there.
     */
    private void carriedByLift() {
        boolean inCabin = HospitalFloor.LIFT_LANDINGS.stream().anyMatch(l -> l.cabin().equals(lastNodeId));
        if (!inCabin || driving) {
            return;
        }
        String at = floor.waypointAt(robot.position());
        if (!at.equals(lastNodeId) && HospitalFloor.LIFT_LANDINGS.stream().anyMatch(l -> l.cabin().equals(at))) {
            log.accept("agv " + serial + ": carried by the lift from " + lastNodeId + " to " + at);
            lastNodeId = at;
        }
    }

    /**
     * The node the AGV stands on: a lobby's parking spot or its dock when on one (finer than the models' waypoints, as the
     * traffic map has them), else the models' waypoint of its position.
     */
    private String nodeHere() {
        return LobbyParking.placeAt(robot.position()).orElse(courier.robotActor().loc().name());
    }

    /** Drives back to the edge's start node after a failed drive along it (see {@code SimulatedCourier.backTo}). */
    private boolean backOff(Edge e) {
        boolean parking = LobbyParking.isPlace(e.startNodeId()) || LobbyParking.isPlace(e.endNodeId());
        boolean back = parking ? courier.robotActor().parkBack(e.startNodeId())
                : courier.robotActor().backTo(objects.waypoint(e.startNodeId()), objects.waypoint(e.endNodeId()));
        log.accept("agv " + serial + ": " + (back ? "backed off to " + e.startNodeId() : "could not back off to " + e.startNodeId()
                + " (" + courier.log().lastFailure().orElse("?") + "), stands at " + courier.robotActor().loc()));
        return back;
    }

    private boolean traverse(Edge e) {
        if (LobbyParking.isPlace(e.startNodeId()) || LobbyParking.isPlace(e.endNodeId())) {
            return courier.robotActor().park(e.startNodeId(), e.endNodeId()); // a lane of the lobby's parking: a plain drive
        }
        WayPoint src = objects.waypoint(e.startNodeId());
        WayPoint dst = objects.waypoint(e.endNodeId());
        for (Action a : e.actions()) {
            // the world's devices as edge actions (./triad run --robots vda5050: drives any model this way): the building
            // this AGV lives in opens the door or brings the lift itself, as the hospital's world binding does over the broker
            if (a.actionType().equals("passDoor")) {
                List<String> doors = objects.doors().stream().map(d -> d.name()).toList();
                return courier.worldActor().passDoor(objects.door(parameter(a, "doorId", doors)), src, dst);
            }
            if (a.actionType().equals("ride")) {
                List<String> lifts = objects.lifts().stream().map(l -> l.name()).toList();
                return courier.worldActor().ride(objects.lift(parameter(a, "liftId", lifts)), src, dst);
            }
            String person = parameter(a, "personId", HospitalFloor.PEOPLE.keySet());
            if (a.actionType().equals("guide")) {
                return courier.robotActor().guide(objects.person(person), src, dst);
            }
            return courier.worldActor().walk(objects.person(person), src, dst);
        }
        return courier.robotActor().move(src, dst);
    }

    private boolean nodeActions(Node n) {
        WayPoint w = objects.waypoint(LobbyParking.waypointOf(n.nodeId()));
        for (Action a : n.actions()) {
            setStatus(a, ActionStatus.RUNNING, null);
            publishState();
            boolean ok;
            String why;
            try {
                ok = switch (a.actionType()) {
                    case "pick" -> courier.robotActor().pick(objects.item(parameter(a, "loadId", HospitalFloor.ITEMS)), w);
                    case "drop" -> courier.robotActor().drop(objects.item(parameter(a, "loadId", HospitalFloor.ITEMS)), w);
                    case "startCharging" -> courier.robotActor().recharge(w);
                    default -> courier.robotActor().startFollowing(objects.person(parameter(a, "personId", HospitalFloor.PEOPLE.keySet())), w);
                };
                why = ok ? null : courier.log().lastFailure().orElse("failed");
            } catch (IllegalArgumentException unknown) {
                ok = false;
                why = "REFUSED: " + unknown.getMessage();
            }
            setStatus(a, ok ? ActionStatus.FINISHED : ActionStatus.FAILED, why);
            if (!ok) {
                log.accept("agv " + serial + ": " + a.actionType() + " at " + n.nodeId() + " failed: " + why);
                return false;
            }
        }
        return true;
    }

    /**
     * The action's parameter {@code key}; failing that, the first parameter naming one of {@code known}, so that
     * master controls that name parameters after the models' ({@code pick(i, w)}: {@code i=gauze}) are understood.
     */
    private static String parameter(Action a, String key, java.util.Collection<String> known) {
        Object v = a.parameter(key);
        if (v == null && a.actionParameters() != null) {
            v = a.actionParameters().stream().map(p -> String.valueOf(p.value())).filter(known::contains).findFirst().orElse(null);
        }
        if (v == null) {
            throw new IllegalArgumentException(a.actionType() + " needs the parameter " + key + " (one of " + known + ")");
        }
        return String.valueOf(v);
    }

    private void abortOrder(String why) {
        for (ActionState s : List.copyOf(actionStates.values())) {
            if (s.actionStatus() == ActionStatus.WAITING) {
                actionStates.put(s.actionId(), new ActionState(s.actionId(), s.actionType(), null, ActionStatus.FAILED, "order aborted: " + why));
            }
        }
        pendingNodes.clear();
        pendingEdges.clear();
        publishState();
        drawPicture();
    }

    private void finishCancel() {
        cancelRequested = false;
        if (cancelActionId != null) {
            ActionState s = actionStates.get(cancelActionId);
            actionStates.put(cancelActionId, new ActionState(cancelActionId, s.actionType(), null, ActionStatus.FINISHED, null));
            cancelActionId = null;
        }
    }

    private void instantAction(Action a) {
        actionStates.put(a.actionId(), waiting(a));
        switch (a.actionType()) {
            case "cancelOrder" -> {
                if (pendingEdges.isEmpty() && pendingNodes.isEmpty()) {
                    setStatus(a, ActionStatus.FAILED, "no order to cancel");
                    error("noOrderToCancel", "cancelOrder without an active order", List.of(new Reference("actionId", a.actionId())));
                } else {
                    cancelRequested = true;
                    cancelActionId = a.actionId();
                    setStatus(a, ActionStatus.RUNNING, null);
                }
            }
            case "startPause" -> {
                robot.setPaused(true);
                setStatus(a, ActionStatus.FINISHED, null);
            }
            case "stopPause" -> {
                robot.setPaused(false);
                setStatus(a, ActionStatus.FINISHED, null);
            }
            case "factsheetRequest" -> {
                send(Topic.FACTSHEET, HospitalFactsheet.of(serial, headerIds.next(Topic.FACTSHEET)), true);
                setStatus(a, ActionStatus.FINISHED, null);
            }
            case "stateRequest" -> setStatus(a, ActionStatus.FINISHED, null);
            default -> {
                setStatus(a, ActionStatus.FAILED, "unsupported instant action");
                error("validationError", "instant action '" + a.actionType() + "' is not supported", List.of(new Reference("actionId", a.actionId())));
            }
        }
    }

    /**
     * Runs while this AGV's robot drives (its thread waits for the clock; under the clock's lock, about every 50 ms):
     * handles the messages that arrive meanwhile (order updates, cancel, pause) and publishes state and
     * visualization when due.
     */
    private void whileDriving() {
        if (!running) {
            return;
        }
        Received r;
        while ((r = inbox.poll()) != null) {
            handle(r, true);
        }
        stateIfDue();
        visualizationIfDue();
    }

    private boolean stateDue() {
        return System.nanoTime() - lastStateNanos >= 1_000_000_000L;
    }

    private void stateIfDue() {
        if (stateDue()) {
            publishState();
        }
    }

    private void visualizationIfDue() {
        if (System.nanoTime() - lastVisualizationNanos >= 250_000_000L) {
            lastVisualizationNanos = System.nanoTime();
            send(Topic.VISUALIZATION, new Visualization(headerIds.next(Topic.VISUALIZATION), HeaderIds.now(), Header.VERSION,
                    MasterControl.TRIAD, serial, position(), velocity()), false);
        }
    }

    private void publishState() {
        lastStateNanos = System.nanoTime();
        statesSent++;
        send(Topic.STATE, state(), false);
    }

    AgvState state() {
        List<NodeState> nodeStates = pendingNodes.stream().filter(n -> n.sequenceId() > lastNodeSequenceId)
                .map(n -> new NodeState(n.nodeId(), n.sequenceId(), null, null, n.released())).toList();
        List<EdgeState> edgeStates = pendingEdges.stream().map(e -> new EdgeState(e.edgeId(), e.sequenceId(), null, e.released())).toList();
        List<Load> loads = robot.carried().stream().map(i -> new Load(i.name(), "item", null)).toList();
        return new AgvState(headerIds.next(Topic.STATE), HeaderIds.now(), Header.VERSION, MasterControl.TRIAD, serial, orderId,
                orderUpdateId, null, lastNodeId, lastNodeSequenceId, nodeStates, edgeStates, position(), velocity(), loads, driving, robot.isPaused(),
                null, null, List.copyOf(actionStates.values()), new BatteryState(robot.battery().percent(), robot.battery().isCharging()), "AUTOMATIC", List.copyOf(errors), information(),
                new SafetyState("NONE", false));
    }

    /** Facts the models need that VDA 5050 has no field for: whom the courier follows, and model edges it knows a closed door on. */
    private List<Information> information() {
        List<Information> info = new ArrayList<>();
        for (generated.hospital.domain.Person p : objects.people()) {
            if (courier.robotActor().following(p)) {
                info.add(new Information("following", List.of(new Reference("personId", p.name())), "following " + p.name(), "INFO"));
            }
        }
        List<String> wps = floor.modelWaypoints();
        for (String a : wps) {
            for (String b : wps) {
                Optional<List<String>> route = floor.route(a, b);
                if (route.isEmpty()) {
                    continue;
                }
                for (String door : floor.doorsOn(route.get())) {
                    if (robot.knownClosedDoors().contains(door)) {
                        info.add(new Information("blockedEdge", List.of(new Reference("edgeId", a + "-" + b)), "door '" + door + "' is closed",
                                "INFO"));
                    }
                }
            }
        }
        return info;
    }

    private AgvPosition position() {
        Vec2 p = robot.position();
        return new AgvPosition(p.x(), p.y(), normalized(robot.heading()), mapId(HospitalFloor.floorAt(p.x())), true);
    }

    private Velocity velocity() {
        Vec2 v = robot.velocity();
        return new Velocity(v.x(), v.y(), null);
    }

    private static double normalized(double theta) {
        double t = Math.IEEEremainder(theta, 2 * Math.PI);
        return Math.max(-Math.PI, Math.min(Math.PI, t));
    }

    private void error(String type, String description, List<Reference> refs) {
        errors.add(new AgvError(type, refs.isEmpty() ? null : refs, description, ErrorLevel.WARNING));
    }

    private static ActionState waiting(Action a) {
        return new ActionState(a.actionId(), a.actionType(), null, ActionStatus.WAITING, null);
    }

    private void setStatus(Action a, ActionStatus status, String result) {
        actionStates.put(a.actionId(), new ActionState(a.actionId(), a.actionType(), null, status, result));
    }

    private static String describe(List<Node> nodes, List<Edge> edges) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < nodes.size(); i++) {
            if (i > 0) {
                Edge e = edges.get(i - 1);
                b.append(e.actions().isEmpty() ? " -> " : " -" + e.actions().get(0).actionType() + "-> ");
            }
            b.append(nodes.get(i).nodeId());
            nodes.get(i).actions().forEach(a -> b.append(" [").append(a.actionType()).append(' ')
                    .append(a.actionParameters() == null ? "" : a.actionParameters().get(0).value()).append(']'));
        }
        return b.toString();
    }

    private void drawPicture() {
        if (pictures != null) {
            TracePicture.writePng(sim, pictures.resolve(serial + ".png"));
        }
    }


    /** Reports OFFLINE (retained) and disconnects cleanly, so no last will is sent; draws the picture. */
    @Override
    public void close() {
        running = false;
        thread.interrupt();
        try {
            thread.join(5000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        if (link != null) {
            send(Topic.CONNECTION, new Connection(headerIds.next(Topic.CONNECTION), HeaderIds.now(), Header.VERSION,
                    MasterControl.TRIAD, serial, ConnectionState.OFFLINE), true);
        }
        sender.shutdown();
        try {
            sender.awaitTermination(5, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        if (link != null) {
            link.close();
        }
        if (ownsBuilding) {
            hospital.stop();
        }
        Optional<SimulationClock> clock = hospital.clock().filter(SimulationClock::isRunning);
        if (clock.isPresent()) {
            clock.get().run(s -> drawPicture());
        } else {
            drawPicture();
        }
    }
}
