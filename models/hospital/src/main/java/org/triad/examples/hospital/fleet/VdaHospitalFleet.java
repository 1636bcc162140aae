package org.triad.examples.hospital.fleet;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;

import org.triad.building.BuildingContext;
import org.triad.examples.hospital.HospitalFloor;
import org.triad.examples.hospital.LobbyParking;
import org.triad.examples.hospital.vda5050.LobbyRoutes;
import org.triad.examples.hospital.vda5050.HospitalTraffic;
import org.triad.examples.hospital.vda5050.VdaHospital;
import org.triad.refarc.ActionRunner;
import org.triad.refarc.StateSource;
import org.triad.refarc.fleet.Battery;
import org.triad.refarc.fleet.FleetChanges;
import org.triad.refarc.fleet.FleetContext;
import org.triad.refarc.fleet.FleetRobot;
import org.triad.refarc.fleet.FloorMap;
import org.triad.refarc.fleet.Pose;
import org.triad.refarc.fleet.RobotPlatformProvider;
import org.triad.vda5050.master.AgvDiscovery;
import org.triad.vda5050.master.MasterControl;
import org.triad.vda5050.master.RemoteAgv;
import org.triad.vda5050.master.TrafficControl;
import org.triad.vda5050.master.DoorKeeper;
import org.triad.vda5050.devices.DeviceLink;
import org.triad.vda5050.devices.DeviceWatch;
import org.triad.vda5050.master.VdaTimeouts;

import generated.hospital.HospitalActionExecutor;
import generated.hospital.HospitalStateProvider;

/**
 * Scheme {@code vda5050} of the hospital application: {@code vda5050:tcp://HOST:PORT[,wait=S][,allow=P+P]}
 * drives every hospital courier (manufacturer {@code triad}) that is ONLINE on that broker, found on the
 * {@code connection} topic within S seconds (default 2; a larger S is an upper bound for a slow broker or machine:
 * once a courier has joined and every announced one is decided, the start waits no longer than the default), and
 * those that come later, through one
 * {@link MasterControl} and its {@link AgvDiscovery}: an AGV must publish a factsheet listing the actions
 * the couriers are sent ({@link #REQUIRED_ACTIONS}), report a state on a waypoint of the hospital and,
 * with {@code allow}, have a serial number matching one of the patterns ({@code *} for any characters);
 * otherwise it is refused with the reason. Each is a robot of the fleet named after its serial number,
 * whose state is what the AGV reports (its last node, its loads, its position and battery) and whose
 * actions are VDA 5050 orders ({@code ./triad robot --broker URL --count N} starts such AGVs). One that
 * goes OFFLINE or CONNECTIONBROKEN for longer than the reconnect grace leaves the fleet until it is back.
 *
 * <p>The couriers drive under one {@link TrafficControl} over the hospital's floor map ({@link HospitalTraffic}):
 * each move and guide reserves its lane, the doors and the single-lane side corridor it passes first (the order's
 * base; the rest its horizon), a courier waits for a held one instead of failing, and fails its action with
 * the reason after {@code traffic=S} seconds (default {@value #TRAFFIC_WAIT_SECONDS}; RefArc re-plans). Each
 * courier is placed on the map where it reports it stands as it joins; one that leaves is lost there until it
 * is back. Its waits show on the operator page, and its expected waits are the planner's congestion costs.
 * {@code traffic=off} drives every edge at once, as before traffic control (robots may then meet head to head).
 */
public final class VdaHospitalFleet implements RobotPlatformProvider {
    public static final double DEFAULT_WAIT_SECONDS = 2;

    @Override
    public String application() {
        return "Hospital";
    }

    @Override
    public String scheme() {
        return "vda5050";
    }

    @Override
    public String usage() {
        return "vda5050:tcp://HOST:PORT[,wait=S][,allow=SERIAL+SERIAL*][,traffic=S|off][,silence=S]  the hospital couriers ONLINE on that VDA 5050 broker, and those that come later, driven under traffic control";
    }

    @Override
    public List<FleetRobot> connect(String argument, FleetContext context) throws Exception {
        String[] parts = argument.split(",");
        String broker = parts[0].trim();
        double wait = DEFAULT_WAIT_SECONDS;
        double trafficBound = TRAFFIC_WAIT_SECONDS;
        List<String> allowed = List.of();
        VdaTimeouts timeouts = VdaTimeouts.defaults();
        for (int i = 1; i < parts.length; i++) {
            String[] kv = parts[i].split("=", 2);
            if (kv.length == 2 && kv[0].trim().equals("silence")) {
                timeouts = withSilence(timeouts, kv[1].trim());
                continue;
            }
            if (kv.length == 2 && kv[0].trim().equals("traffic")) {
                trafficBound = trafficBound(kv[1].trim());
                continue;
            }
            if (kv.length == 2 && kv[0].trim().equals("allow")) {
                allowed = List.of(kv[1].trim().split("\\+"));
                if (allowed.stream().anyMatch(a -> !a.matches("[A-Za-z0-9_*-]+"))) {
                    throw new IllegalArgumentException("vda5050:...,allow=S1+S2 takes serial numbers (letters, digits, '-', '_', '*' for any), not '" + kv[1] + "'");
                }
                continue;
            }
            if (kv.length != 2 || !kv[0].trim().equals("wait")) {
                throw new IllegalArgumentException("vda5050: unknown option '" + parts[i] + "'; " + usage());
            }
            try {
                wait = Double.parseDouble(kv[1].trim());
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("vda5050:...,wait=S takes seconds, not '" + kv[1] + "'");
            }
            if (!(wait > 0) || wait > 600) {
                throw new IllegalArgumentException("vda5050:...,wait=S takes 0 to 600 seconds, not " + kv[1]);
            }
        }
        MasterControl master = MasterControl.connect(broker, timeouts, line -> System.err.println("triad serve: " + line));
        TrafficControl traffic = trafficBound == 0 ? null
                : new TrafficControl(HospitalTraffic.map(new HospitalFloor()), trafficBound, line -> System.err.println("triad serve: " + line));
        if (traffic != null && context instanceof BuildingContext building) {
            building.traffic().add(traffic::waiting); // the operator page's "Waiting for traffic"
            org.triad.runtime.schema.ActionCosts congestion = traffic.congestion(SECONDS_PER_MOVE);
            building.traffic().addCosts(congestion); // the planner prices moves by their expected wait
            building.traffic().addCosts(leadingAPerson(congestion));
        }
        AutoCloseable doors = traffic == null ? null : keepDoors(master, traffic);
        DeviceWatch watch = new DeviceWatch(DeviceLink.over(master.link(), line -> System.err.println("triad serve: " + line)));
        if (context instanceof BuildingContext building) {
            building.devices().add(watch::devices); // the operator page's doors and lifts
        }
        Roster roster = new Roster(master, context.changes(), traffic);
        AgvDiscovery discovery = new AgvDiscovery(master, new AgvDiscovery.Requirements(MasterControl.TRIAD, allowed, REQUIRED_ACTIONS,
                Math.max(wait, FACTSHEET_SECONDS), timeouts.reconnectGraceSeconds()), roster, line -> System.err.println("triad serve: " + line));
        long start = System.nanoTime();
        long deadline = start + (long) (wait * 1e9);
        // a long wait is for a slow machine or broker (a retained ONLINE can take seconds to arrive under load):
        // it ends early once a courier is there, but never before the default, so that couriers announced together join together
        long enough = start + (long) (Math.min(wait, DEFAULT_WAIT_SECONDS) * 1e9);
        while (System.nanoTime() < deadline && !(System.nanoTime() >= enough && roster.anyJoined() && discovery.settled())) {
            Thread.sleep(50);
        }
        // the AGVs announced by then are decided on before the service starts (their first state may be a moment late)
        long settle = System.nanoTime() + (long) (FACTSHEET_SECONDS * 1e9) + 2 * AgvDiscovery.POLL_MILLIS * 1_000_000L;
        while (!discovery.settled() && System.nanoTime() < settle) {
            Thread.sleep(50);
        }
        Runnable closeAll = () -> {
            discovery.close();
            if (doors != null) {
                try {
                    doors.close();
                } catch (Exception e) {
                    System.err.println("triad serve: closing the doors' link: " + e.getMessage());
                }
            }
            watch.close();
            master.close();
        };
        List<FleetRobot> robots = roster.handOver(closeAll);
        if (robots.isEmpty()) {
            closeAll.run();
            throw new IllegalStateException("no hospital courier (manufacturer '" + MasterControl.TRIAD + "') announced itself ONLINE on " + broker
                    + " within " + wait + " s (topic uagv/v2/" + MasterControl.TRIAD + "/+/connection)" + roster.refusals()
                    + "; start them with './triad robot --broker " + broker + " --count N'");
        }
        return robots;
    }

    /** The hospital's rooms, walls, doors and waypoints, taken from the simulation once, when the first courier draws its map. */
    private static final java.util.function.Supplier<FloorMap> LAYOUT = new java.util.function.Supplier<>() {
        private FloorMap layout;

        @Override
        public synchronized FloorMap get() {
            if (layout == null) {
                layout = SimulatedHospitalRobot.layout();
            }
            return layout;
        }
    };

    /**
     * The building's doors (served as devices on the same broker by {@code ./triad robot}) tied to the door
     * reservations: opened for the robot granted a way through, closed once nobody holds or waits for them. Asked over
     * master control's connection (on a secured broker as master control, which the ACL lets ask devices).
     */
    private static AutoCloseable keepDoors(MasterControl master, TrafficControl traffic) {
        DeviceLink link = DeviceLink.over(master.link(), line -> System.err.println("triad serve: " + line));
        DoorKeeper keeper = new DoorKeeper(link, HospitalTraffic.keptDoors(new HospitalFloor()), DOOR_SECONDS,
                line -> System.err.println("triad serve: " + line));
        traffic.keepDoors(keeper);
        return () -> {
            keeper.close();
            link.close();
        };
    }

    /** How long a door may take to open for a courier before its move fails with the reason. */
    static final double DOOR_SECONDS = 30;

    /** How long a courier may wait for a lane, a door or a corridor before its move fails with the reason (RefArc re-plans). */
    static final double TRAFFIC_WAIT_SECONDS = 120;

    /**
     * One step more for an action that takes a person along (the courier's {@code guide}, the building's {@code walk}): with
     * it free, a plan for {@code GoTo(storage)} from the lobby guided Alice out of it as readily as it drove (the same
     * number of steps), and the service's mixed benchmark sent six couriers in a row to lead Alice, whom another task
     * held, out of the lobby (each failed {@code PERSON_LOST}: she was 13 to 20 m away with the courier guiding her). A
     * person is led only where a goal needs it.
     */
    static final org.triad.runtime.schema.ActionCosts LEADING_A_PERSON = action -> action.args().stream()
            .anyMatch(a -> a instanceof org.triad.runtime.app.DomainObject o && HospitalFloor.PEOPLE.containsKey(o.name())) ? 1 : 0;

    /**
     * {@link #LEADING_A_PERSON}, and the congestion of the edge a guide or walk drives (its last two arguments), as a move
     * along it would cost: congestion prices actions of two waypoints only, so a guide along a congested edge came out
     * cheaper than the move (the benchmark's second run planned {@code guide(alice, c6, c5)} for a patrol).
     */
    static org.triad.runtime.schema.ActionCosts leadingAPerson(org.triad.runtime.schema.ActionCosts congestion) {
        return action -> {
            double person = LEADING_A_PERSON.extra(action);
            if (person == 0 || action.args().size() < 3) {
                return person;
            }
            List<Object> edge = action.args().subList(action.args().size() - 2, action.args().size());
            return person + congestion.extra(new org.triad.runtime.app.GroundAction(action.actor(), "move", edge));
        };
    }

    /** A move's typical time (one model edge at the couriers' speed): the unit congestion costs count expected waits in. */
    static final double SECONDS_PER_MOVE = 10;

    /**
     * {@code silence=S}: how long an order may go without a state message from its AGV before it fails (default
     * {@code VdaTimeouts.defaults()}'s 5 s; an AGV sends one at least every second). A loaded machine or network wants more.
     */
    private static VdaTimeouts withSilence(VdaTimeouts t, String value) {
        double s;
        try {
            s = Double.parseDouble(value);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("vda5050:...,silence=S takes seconds, not '" + value + "'");
        }
        if (!(s > 0) || s > 600) {
            throw new IllegalArgumentException("vda5050:...,silence=S takes 0 to 600 seconds, not " + value);
        }
        return new VdaTimeouts(t.onlineSeconds(), s, t.actionSeconds(), t.reconnectGraceSeconds());
    }

    private static double trafficBound(String value) {
        if (value.equals("off")) {
            return 0;
        }
        double s;
        try {
            s = Double.parseDouble(value);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("vda5050:...,traffic=S takes the seconds a courier may wait for traffic, or 'off', not '" + value + "'");
        }
        if (!(s > 0) || s > 3600) {
            throw new IllegalArgumentException("vda5050:...,traffic=S takes 0 to 3600 seconds (or 'off'), not " + value);
        }
        return s;
    }

    /** The actions {@link org.triad.examples.hospital.vda5050.VdaCourier} sends: an AGV whose factsheet lacks one cannot serve the hospital. */
    static final java.util.Set<String> REQUIRED_ACTIONS = java.util.Set.of("pick", "drop", "guide", "startFollowing");
    /** How long reading a courier's state waits for an order a previous master sent to end (one edge at walking speed and more). */
    static final double AT_REST_SECONDS = 60;
    /** How long an AGV that announced itself may take to publish its factsheet and first state. */
    static final double FACTSHEET_SECONDS = 5;

    /**
     * The discovery's reports as the fleet's: the couriers that joined before the service took over are
     * handed over as its first robots, later ones join the running fleet; a joined AGV whose reported node
     * is not a waypoint of the hospital is refused.
     */
    private static final class Roster implements AgvDiscovery.Listener {
        private final MasterControl master;
        private final FleetChanges changes;
        private final TrafficControl traffic;
        private final Map<String, Courier> couriers = new TreeMap<>();
        private final Map<String, String> refused = new TreeMap<>();
        private List<FleetRobot> early = new ArrayList<>();
        private Runnable closeAll;
        private int open;

        Roster(MasterControl master, FleetChanges changes, TrafficControl traffic) {
            this.master = master;
            this.changes = changes;
            this.traffic = traffic;
        }

        /** Puts the AGV on the traffic map where it reports it stands, so that nobody is sent into its place; a reason if it cannot be. */
        private Optional<String> placed(RemoteAgv agv) {
            if (traffic == null) {
                return Optional.empty();
            }
            String node = agv.state().map(s -> s.lastNodeId()).orElse(null);
            if (node == null || !traffic.read(t -> t.map().hasNode(node))) {
                return Optional.of("it reports node '" + node + "', which is not on the hospital's traffic map");
            }
            if (!traffic.place(agv.name(), node)) {
                return Optional.of("its node '" + node + "' is full on the traffic map (" + traffic.read(t -> t.map().node(node).capacity()) + " robots)");
            }
            if (node.equals(LobbyParking.HALL)) {
                // it joins on the lobby's centre, everyone's way in and out (a courier alone in its building starts there; one
                // may have stopped there): it parks on a free spot first, a reserved drive, so the next one can join and leave
                LobbyRoutes.of(traffic).freeSpot(agv.name()).ifPresent(spot -> {
                    if (!agv.driveRoute(List.of(LobbyParking.HALL, spot), traffic)) {
                        System.err.println("triad serve: " + agv.serialNumber() + " joined on the lobby's centre and could not park on "
                                + spot + ": " + agv.lastFailure().orElse("?"));
                    }
                });
            }
            return Optional.empty();
        }

        synchronized List<FleetRobot> handOver(Runnable closeAll) {
            this.closeAll = closeAll;
            List<FleetRobot> first = early;
            early = null;
            first.sort(java.util.Comparator.comparing(FleetRobot::name)); // fleet order by name, not by who answered first
            return first;
        }

        /** Whether a courier has joined before the hand-over. */
        synchronized boolean anyJoined() {
            return early != null && !early.isEmpty();
        }

        synchronized String refusals() {
            return refused.isEmpty() ? "" : "; refused: " + refused.entrySet().stream().map(e -> e.getKey() + " (" + e.getValue() + ")").toList();
        }

        @Override
        public Optional<String> appeared(RemoteAgv agv) {
            Courier c;
            synchronized (this) {
                c = couriers.get(agv.serialNumber());
                if (c == null) {
                    c = new Courier(agv.serialNumber(), new VdaHospital(master, agv.serialNumber(), traffic), this::closed);
                }
            }
            try {
                c.stateSource().currentState();
            } catch (Exception e) {
                return Optional.of("the hospital cannot read its state: " + e.getMessage());
            }
            Optional<String> offMap = placed(agv);
            if (offMap.isPresent()) {
                return Optional.of("traffic control cannot place it: " + offMap.get());
            }
            synchronized (this) {
                refused.remove(agv.serialNumber());
                if (couriers.put(agv.serialNumber(), c) == null) {
                    open++;
                }
                if (early != null) {
                    early.add(c);
                    return Optional.empty();
                }
            }
            changes.joined(c);
            return Optional.empty();
        }

        @Override
        public void gone(RemoteAgv agv, String reason) {
            if (traffic != null) {
                traffic.lost(agv.name(), reason); // it may stand anywhere: nobody is driven into it until it is back
            }
            changes.left(agv.serialNumber(), reason);
        }

        @Override
        public void back(RemoteAgv agv) {
            Courier c;
            synchronized (this) {
                c = couriers.get(agv.serialNumber());
            }
            if (c != null) {
                Optional<String> offMap = placed(agv);
                if (offMap.isPresent()) {
                    System.err.println("triad serve: " + agv.serialNumber() + " is back but traffic control cannot place it: " + offMap.get());
                    return;
                }
                changes.joined(c);
            }
        }

        @Override
        public void refused(String serialNumber, String reason) {
            synchronized (this) {
                refused.put(serialNumber, reason);
            }
            changes.refused(serialNumber, reason);
        }

        /** The service closes each robot once; the connection goes with the last. */
        private void closed() {
            Runnable all;
            synchronized (this) {
                all = --open <= 0 ? closeAll : null;
            }
            if (all != null) {
                all.run();
            }
        }
    }

    /** One AGV as a robot of the fleet: the generated StateProvider and ActionExecutor over the VDA 5050 binding. */
    private static final class Courier implements FleetRobot {
        private final String name;
        private final StateSource state;
        private final ActionRunner actions;
        private final Runnable onClose;

        private final RemoteAgv agv;
        private final VdaHospital hospital;

        /** Off the ground floor's corridor into the lobby when its task left it on a junction ({@link org.triad.examples.hospital.vda5050.VdaCourier#parkOutOfTheWay}). */
        @Override
        public Optional<String> parkOutOfTheWay() {
            return hospital.courier().parkOutOfTheWay();
        }

        Courier(String name, VdaHospital agv, Runnable onClose) {
            this.name = name;
            this.hospital = agv;
            this.onClose = onClose;
            this.agv = agv.courier().agv();
            StateSource generated = new HospitalStateProvider(agv.courier(), agv.building());
            RemoteAgv remote = agv.courier().agv();
            // read between the fleet's own orders: an order still running was sent by a master before (a service
            // restarted mid-task), so the state is read where that order leaves the AGV, and its moves are not sent again
            this.state = () -> {
                remote.awaitAtRest(AT_REST_SECONDS);
                return generated.currentState();
            };
            this.actions = new HospitalActionExecutor(agv.courier(), agv.building());
        }

        @Override
        public String name() {
            return name;
        }

        @Override
        public StateSource stateSource() {
            return state;
        }

        @Override
        public ActionRunner actionRunner() {
            return actions;
        }

        @Override
        public Optional<Pose> pose() {
            return agv.state().map(s -> s.agvPosition()).filter(p -> p != null && p.positionInitialized())
                    .map(p -> new Pose(p.x(), p.y(), p.theta(), p.mapId()));
        }

        /** The hospital's layout with this courier where its state says it is (a VDA 5050 AGV draws no map). */
        @Override
        public Optional<FloorMap> floor() {
            FloorMap m = LAYOUT.get();
            Optional<Pose> p = pose();
            List<FloorMap.Mark> robots = p.map(q -> List.of(new FloorMap.Mark(name, q.x(), q.y(), agv.state().map(s -> s.loads() == null ? ""
                    : String.join(", ", s.loads().stream().map(l -> l.loadId()).toList())).orElse("")))).orElse(List.of());
            return Optional.of(new FloorMap(0, m.bounds(), m.areas(), m.walls(), m.doors(), m.waypoints(), robots, List.of(), List.of()));
        }

        /** One map per floor, with this courier on its own floor's. */
        @Override
        public Map<String, FloorMap> floors() {
            return HospitalMaps.perFloor(floor().orElseThrow());
        }

        @Override
        public Optional<Battery> battery() {
            return agv.state().map(s -> s.batteryState()).filter(b -> b != null).map(b -> new Battery(b.batteryCharge(), b.charging()));
        }

        @Override
        public void close() {
            hospital.close();
            onClose.run();
        }
    }
}
