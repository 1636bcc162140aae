package org.triad.examples.hospital.vda5050;

import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.triad.building.ChargeReserve;
import org.triad.building.traffic.Resource.Kind;
import org.triad.building.traffic.TrafficMap;
import org.triad.building.traffic.TrafficStats;
import org.triad.examples.hospital.HospitalFloor;
import org.triad.examples.hospital.HospitalObjects;
import org.triad.examples.hospital.LobbyParking;
import org.triad.vda5050.broker.MosquittoBroker;
import org.triad.vda5050.devices.DeviceLink;
import org.triad.vda5050.master.DoorKeeper;
import org.triad.vda5050.master.MasterControl;
import org.triad.vda5050.master.RemoteAgv;
import org.triad.vda5050.master.TrafficControl;
import org.triad.vda5050.master.VdaTimeouts;
import org.triad.vda5050.protocol.AgvState;

/**
 * Traffic in the dyn4j building (issue #21's "Measured"): N couriers in ONE simulated hospital ({@code ./triad robot
 * --count N}, its own JVM, a real Mosquitto), each doing random deliveries (to a random room, then to another) and
 * patrols (three random corridor waypoints) on both floors (the lift between them) for a stretch of simulated time, once under traffic control
 * ({@link TrafficControl} over {@link HospitalTraffic}'s map, doors kept by a {@link DoorKeeper}) and once without
 * (each edge driven at once: the robots meet in the building). Prints one row per fleet and mode: physical contacts
 * the building reported, standstills (60 simulated seconds in which no courier with a task reached a node), tasks
 * completed per simulated hour, drives that failed, waits for doors and corridors/lanes (median, p95, max, in
 * simulated seconds) and the master's CPU (this JVM: master control, traffic control, the couriers' loops).
 * Guides need people and are left out (the building has two, Alice and Bob, not one a courier). A courier's battery
 * drains 0.5 % a metre (issue #22): it takes its next leg only if its charge covers the leg, the way back to the dock and
 * a margin ({@link ChargeReserve} on the traffic map's lanes, {@value #MARGIN_PERCENT} %), else it drives to the dock (a
 * node of the traffic map, {@link LobbyParking#DOCK}: couriers queue for it in the reservation table), urgent (rule 3's
 * precedence case) when its charge is below its reserve where it stands, and charges first (waiting on a free lobby spot
 * while the dock is taken); without charging every courier ran flat after some 200 m and stood, and the rows measured
 * dead couriers. A courier whose battery runs empty all the same is lost on the traffic map, waits for
 * the building's staff, who swap its battery where it stands after {@value #RESCUE_AFTER_SECONDS} simulated seconds
 * ({@code --rescue-after}), and every such rescue is a column of the table.
 *
 * <pre>
 * mvn -B -q -pl models/hospital -am package -DskipTests
 * java -cp "$(cat models/hospital/target/classpath.txt):models/hospital/target/classes:models/hospital/target/test-classes" \
 *     org.triad.examples.hospital.vda5050.BuildingTrafficBenchmark [simulated-minutes=30] [speed=10] [fleets=2,5,10,20] [seed=1] [both|reserved|unreserved]
 * </pre>
 */
public final class BuildingTrafficBenchmark {
    private static final Pattern SIMULATED = Pattern.compile("building: ([0-9.]+) s simulated in ([0-9.]+) s");
    /**
     * The rooms deliveries go to: all but the lobby, where the couriers start parked (a courier arriving there would
     * drive onto the lobby's waypoint among them).
     */
    private static final List<String> DESTINATIONS = HospitalFloor.ROOMS.stream().filter(r -> !r.equals(HospitalFloor.ROBOT_START)).toList();
    /** The waypoints patrols go by: the corridors of both floors, not the lift's cabins (a courier rides through them). */
    private static final List<String> PATROL = HospitalFloor.CORRIDOR_WAYPOINTS.stream()
            .filter(w -> HospitalFloor.LIFT_LANDINGS.stream().noneMatch(l -> l.cabin().equals(w))).toList();
    /** A standstill: this many simulated seconds in which no courier with a task reached a node. */
    private static final double STANDSTILL = 60;

    private record Row(int robots, boolean reserved, int contacts, int standstills, double longestStill, double simHours, long tasks, long failed,
            List<Double> doorWaits, List<Double> liftWaits, List<Double> laneWaits, double cpuSeconds, long routes, long reservations, long asides, long charges,
            double lowestBattery, int rescues) {
    }

    public static void main(String[] args) throws Exception {
        double minutes = args.length > 0 ? Double.parseDouble(args[0]) : 30;
        double speed = args.length > 1 ? Double.parseDouble(args[1]) : 10;
        List<Integer> fleets = new ArrayList<>();
        for (String f : (args.length > 2 ? args[2] : "2,5,10,20").split(",")) {
            fleets.add(Integer.parseInt(f.trim()));
        }
        long seed = args.length > 3 ? Long.parseLong(args[3]) : 1;
        String modes = args.length > 4 ? args[4] : "both";
        List<Boolean> reservations = switch (modes) {
            case "both" -> List.of(true, false);
            case "reserved" -> List.of(true);
            case "unreserved" -> List.of(false);
            default -> throw new IllegalArgumentException("modes is both, reserved or unreserved, not '" + modes + "'");
        };
        List<Row> rows = new ArrayList<>();
        for (int n : fleets) {
            for (boolean reserved : reservations) {
                Row r = run(n, reserved, minutes, speed, seed);
                rows.add(r);
                System.err.println(format(r));
            }
        }
        System.out.printf(Locale.ROOT, "%n%.0f simulated minutes per run at %.0fx real time, seed %d, both floors of the dyn4j hospital%n", minutes,
                speed, seed);
        System.out.println("| robots | reservations | contacts | standstills | longest still s | tasks/sim-h | dock visits | lowest battery % | rescues | failed drives | steps aside | door waits med/p95/max s (n) | lift waits med/p95/max s (n) | corridor+lane waits med/p95/max s (n) | master CPU ms per robot per sim-min | master CPU ms per route | master CPU ms per reservation |");
        System.out.println("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
        rows.forEach(r -> System.out.println(format(r)));
    }

    private static String format(Row r) {
        return String.format(Locale.ROOT, "| %d | %s | %d | %d | %.0f | %.1f | %d | %.1f | %d | %d | %s | %s | %s | %s | %.1f | %.2f | %s |", r.robots, r.reserved ? "yes" : "no",
                r.contacts, r.standstills, r.longestStill, r.tasks / r.simHours, r.charges, r.lowestBattery, r.rescues, r.failed, r.reserved ? Long.toString(r.asides) : "-", waits(r.doorWaits, r.reserved), waits(r.liftWaits, r.reserved),
                waits(r.laneWaits, r.reserved), r.cpuSeconds * 1000 / r.robots / (r.simHours * 60), r.routes == 0 ? 0 : r.cpuSeconds * 1000 / r.routes,
                r.reservations == 0 ? "-" : String.format(Locale.ROOT, "%.2f", r.cpuSeconds * 1000 / r.reservations));
    }

    private static String waits(List<Double> w, boolean reserved) {
        if (!reserved) {
            return "-";
        }
        if (w.isEmpty()) {
            return "none";
        }
        return String.format(Locale.ROOT, "%.1f/%.1f/%.1f (%d)", TrafficStats.quantile(w, 0.5), TrafficStats.quantile(w, 0.95), Collections.max(w),
                w.size());
    }

    private static Row run(int n, boolean reserved, double minutes, double speed, long seed) throws Exception {
        Path dir = Files.createTempDirectory("traffic-benchmark");
        TrafficMap map = HospitalTraffic.map(new HospitalFloor());
        List<String> log = Collections.synchronizedList(new ArrayList<>());
        long t0 = System.nanoTime();
        // every line of master control and traffic control with the simulated second (at the building's pace) it came at
        java.util.function.Consumer<String> timed = l -> log.add(String.format(Locale.ROOT, "%.1f s: %s", (System.nanoTime() - t0) / 1e9 * speed, l));
        try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"));
                AgvProcess building = AgvProcess.building(broker.url(), n, speed, dir, "--rescue-after", Double.toString(RESCUE_AFTER_SECONDS));
                MasterControl master = MasterControl.connect(broker.url(), VdaTimeouts.defaults(), timed);
                DeviceLink doorLink = DeviceLink.connect(broker.url(), "benchmark-doors", timed);
                DoorKeeper keeper = new DoorKeeper(doorLink, HospitalTraffic.keptDoors(new HospitalFloor()), 30, timed)) {
            // the table runs on the wall clock: a courier may wait 120 simulated seconds at the building's pace
            TrafficControl traffic = new TrafficControl(map, 120 / speed, timed);
            ChargeReserve reserve = new ChargeReserve(map, LobbyParking.DOCK, HospitalObjects.DRAIN_PERCENT_PER_METRE, MARGIN_PERCENT, (a, b) -> path(map, a, b));
            if (reserved) {
                traffic.keepDoors(keeper).stepAside(true);
            }
            List<RemoteAgv> agvs = new ArrayList<>();
            for (int i = 1; i <= n; i++) {
                RemoteAgv a = master.agv("courier-" + i);
                if (!a.awaitOnline()) {
                    throw new IllegalStateException("courier-" + i + " not online: " + building.output());
                }
                agvs.add(a);
            }
            if (reserved) {
                // every courier on the map where it stands before any drives, as a fleet places each robot as it joins: placed at
                // its first drive, a courier starting in a room (19 and 20) found the zone out of the lobby promised to the
                // couriers queued in the lobby, could not be placed, and stood in ward 3 unseen by traffic control
                for (RemoteAgv a : agvs) {
                    if (!traffic.place(a.name(), where(a))) {
                        throw new IllegalStateException(a.name() + " cannot be placed at " + where(a) + " on the traffic map");
                    }
                }
            }
            AtomicBoolean running = new AtomicBoolean(true);
            AtomicLong tasks = new AtomicLong();
            AtomicLong failed = new AtomicLong();
            AtomicLong routes = new AtomicLong();
            AtomicLong charges = new AtomicLong();
            AtomicLong emptied = new AtomicLong();
            Map<String, Long> lastProgress = new ConcurrentHashMap<>();
            Map<String, Boolean> busy = new ConcurrentHashMap<>();
            // what each courier's thread does now: a standstill's report names who waits for what outside the table too
            Map<String, String> phase = new ConcurrentHashMap<>();
            long cpu0 = cpuNanos();
            long start = System.nanoTime();
            List<Thread> threads = new ArrayList<>();
            for (int i = 0; i < n; i++) {
                RemoteAgv agv = agvs.get(i);
                Random random = new Random(seed * 1000 + i);
                long delay = i == 0 ? 0 : 3000; // courier-1 starts on the lobby's dock: it leaves first
                Thread t = new Thread(() -> {
                    sleep(delay);
                    while (running.get()) {
                        List<String> stops = new ArrayList<>();
                        if (random.nextInt(3) < 2) { // a delivery: to a room, then to another
                            stops.add(pick(DESTINATIONS, random));
                            stops.add(pick(DESTINATIONS, random));
                        } else { // a patrol
                            for (int k = 0; k < 3; k++) {
                                stops.add(pick(PATROL, random));
                            }
                        }
                        busy.put(agv.name(), true);
                        boolean ok = true;
                        for (int k = 0; k < stops.size(); k++) {
                            String stop = stops.get(k);
                            boolean charge = false;
                            boolean urgent = false;
                            String from = where(agv);
                            if (batteryEmpty(agv)) {
                                // it cannot drive (master control has it lost where it stands): it waits for the staff's
                                // rescue, with no task, so that the standstills count the couriers that could move
                                emptied.incrementAndGet();
                                timed.accept("benchmark: " + agv.name() + "'s battery is empty at " + from + "; it waits for the staff");
                                busy.put(agv.name(), false);
                                phase.put(agv.name(), "battery empty at " + from + ", waits for the staff");
                                while (running.get() && batteryEmpty(agv)) {
                                    sleep(200);
                                }
                                ok = false;
                                break;
                            }
                            if (!from.equals(LobbyParking.DOCK) && !reserve.covers(battery(agv), path(map, from, stop))) {
                                // to the dock before the next leg: a node of the traffic map for one courier, queued for in
                                // the reservation table like any other (it was a semaphore outside the table, whose waits
                                // closed cycles no rule saw: session 12's standstills); urgent (rule 3's precedence case) only
                                // below its reserve where it stands, the way to the dock and the margin: every courier
                                // urgent on its way to charge jammed the ring (the couriers, charged alike, went at once)
                                urgent = battery(agv) < reserve.reserveAt(from);
                                timed.accept(String.format(Locale.ROOT, "benchmark: %s at %.1f %% charges first%s: %s to %s takes %s", agv.name(), battery(agv),
                                        urgent ? ", urgent" : "", from, stop, reserve.explain(path(map, from, stop))));
                                stop = LobbyParking.DOCK;
                                charge = true;
                                k--;
                            }
                            if (charge && reserved && !LobbyParking.isPlace(from)) {
                                // into the lobby first, onto a free spot, and queue for the dock there, as the fleet's
                                // Recharge(lobby) does: queued on the way (at c4, the lobby's door), a courier held the ring's
                                // node that the dock's holder needed to leave (session 14, admission runs); from the hall's centre
                                // too (a courier that backed off there): asking for the dock, a taken dead end, from there had it
                                // step aside to the first spot by name, between two parked couriers, again and again
                                String spot = LobbyRoutes.of(traffic).spotApart(agv.name()).orElse(null);
                                if (spot != null) {
                                    List<String> in = path(map, from, spot);
                                    routes.incrementAndGet();
                                    phase.put(agv.name(), "drives " + in + " to queue for the dock" + String.format(Locale.ROOT, " (battery %.0f %%)", battery(agv)));
                                    ok = agv.driveRoute(in, traffic, edgeActions(in));
                                    from = where(agv);
                                }
                            }
                            if (ok && !from.equals(stop)) {
                                List<String> path = path(map, from, stop);
                                if (charge && reserved && !LobbyParking.isPlace(from) && dockTaken(traffic, agv.name())) {
                                    // the dock is taken: to a free spot in the lobby first, and from there to the dock (the
                                    // next round of this loop). Waiting at c4 for the dock, it stood on the way out of the
                                    // courier charging there: each waited for the other, and the one at c4 stepped aside
                                    // onto the ring, metres it lacked (the first runs of session 14)
                                    List<String> toSpot = LobbyRoutes.of(traffic).toParking(agv.name(), from);
                                    if (!toSpot.isEmpty()) {
                                        path = toSpot;
                                        charge = false;
                                    }
                                }
                                routes.incrementAndGet();
                                phase.put(agv.name(), "drives " + path + String.format(Locale.ROOT, " (battery %.0f %%)", battery(agv)));
                                ok = reserved ? agv.driveRoute(path, traffic, edgeActions(path), urgent) : driveEdges(agv, path);
                            }
                            if (charge && ok) {
                                phase.put(agv.name(), "charges on the dock");
                                ok = agv.nodeAction(LobbyParking.DOCK, "startCharging", Map.of());
                                charges.incrementAndGet();
                            }
                            lastProgress.put(agv.name(), System.nanoTime());
                            if (!ok) {
                                timed.accept("failed: " + agv.lastFailure().orElse("?"));
                                if (failed.incrementAndGet() <= 10) {
                                    System.err.println("failed: " + agv.lastFailure().orElse("?"));
                                }
                                phase.put(agv.name(), "rests after a failed drive");
                                // in simulated seconds, so that a run does not depend on its speed: one wall second was 40
                                // simulated at 40x, and 7 of the 8 standstills of the first 8-hour 5-courier run (session 14) were a
                                // chain of waits ending at a courier resting on the ring
                                sleep(Math.round(REST_AFTER_FAILURE_SECONDS * 1000 / speed));
                                if (reserved && running.get()) {
                                    // off the ring into the lobby, as the fleet parks a courier whose task ended on a junction
                                    List<String> park = LobbyRoutes.of(traffic).outOfTheWay(agv.name(), where(agv));
                                    if (!park.isEmpty()) {
                                        phase.put(agv.name(), "parks out of the way: " + park);
                                        routes.incrementAndGet();
                                        agv.driveRoute(park, traffic);
                                    }
                                }
                                break;
                            }
                        }
                        busy.put(agv.name(), false);
                        if (ok && running.get()) {
                            tasks.incrementAndGet();
                        }
                    }
                }, "bench-" + agv.name());
                threads.add(t);
                t.start();
            }
            long end = start + (long) (minutes * 60 / speed * 1e9);
            int standstills = 0;
            long stillSince = System.nanoTime();
            Map<String, String> lastNode = new HashMap<>();
            Map<String, Long> nodeSince = new HashMap<>();
            double longestStill = 0;
            double lowestBattery = 100;
            String longestStillOf = "";
            while (System.nanoTime() < end) {
                Thread.sleep(200);
                boolean moved = false;
                long now = System.nanoTime();
                for (RemoteAgv a : agvs) {
                    String node = a.state().map(AgvState::lastNodeId).orElse("");
                    lowestBattery = Math.min(lowestBattery, battery(a));
                    boolean changed = !node.equals(lastNode.put(a.name(), node));
                    moved |= changed && busy.getOrDefault(a.name(), false);
                    if (changed || !busy.getOrDefault(a.name(), false)) {
                        nodeSince.put(a.name(), now);
                    }
                    double still = (now - nodeSince.getOrDefault(a.name(), now)) / 1e9 * speed;
                    if (still > longestStill) {
                        longestStill = still;
                        longestStillOf = a.name() + " at " + node + " (" + phase.getOrDefault(a.name(), "?") + ")";
                    }
                }
                if (moved || busy.values().stream().noneMatch(b -> b)) {
                    stillSince = System.nanoTime();
                } else if ((System.nanoTime() - stillSince) / 1e9 * speed > STANDSTILL) {
                    standstills++;
                    System.err.println("standstill (" + n + " robots, reserved " + reserved + ") at " + Math.round((now - t0) / 1e9 * speed) + " s: " + traffic.waits());
                    for (RemoteAgv a : agvs) {
                        if (busy.getOrDefault(a.name(), false)) {
                            System.err.println("  " + a.name() + ": " + phase.getOrDefault(a.name(), "?") + "; AGV " + a.state().map(s -> "at "
                                    + s.lastNodeId() + (s.driving() ? ", driving" : "") + (s.nodeStates().isEmpty() ? "" : ", order to "
                                    + s.nodeStates().get(s.nodeStates().size() - 1).nodeId()) + s.actionStates().stream()
                                    .filter(x -> x.actionStatus() == org.triad.vda5050.protocol.Messages.ActionStatus.RUNNING)
                                    .map(x -> ", " + x.actionType() + " running").collect(java.util.stream.Collectors.joining())).orElse("?") + "; table "
                                    + traffic.read(t -> t.robots().contains(a.name()) ? "base " + t.base(a.name()) + t.waiting(a.name()).map(w -> ", waits").orElse("") : "-"));
                        }
                    }
                    stillSince = System.nanoTime();
                }
            }
            running.set(false);
            double cpu = (cpuNanos() - cpu0) / 1e9;
            for (Thread t : threads) {
                t.join(120_000);
            }
            building.stop();
            Files.write(dir.resolve("master.log"), new ArrayList<>(log));
            System.err.println("logs (building, master) in " + dir);
            System.err.printf(Locale.ROOT, "longest still: %.0f s, %s%n", longestStill, longestStillOf);
            System.err.printf(Locale.ROOT, "dock: %d charges, lowest battery %.1f %%, %d batteries ran empty, %d rescues%n", charges.get(), lowestBattery,
                    emptied.get(), building.lines("rescue courier-").size());
            building.lines("rescue courier-").forEach(l -> System.err.println("rescue (" + n + " robots, reserved " + reserved + "): " + l));
            Matcher m = SIMULATED.matcher(building.output());
            double simSeconds = (System.nanoTime() - start) / 1e9 * speed;
            while (m.find()) {
                simSeconds = Double.parseDouble(m.group(1));
            }
            int contacts = building.lines("contact courier-").size();
            building.lines("contact courier-").stream().limit(10).forEach(l -> System.err.println("contact (" + n + " robots, reserved " + reserved + "): " + l));
            List<Double> doorWaits = new ArrayList<>();
            List<Double> liftWaits = new ArrayList<>();
            List<Double> laneWaits = new ArrayList<>();
            traffic.read(t -> {
                // the table's clock is the wall clock: its waits in simulated seconds at the building's pace
                t.stats().waits(Kind.DOOR).forEach(w -> doorWaits.add(w * speed));
                t.stats().waits(Kind.LIFT).forEach(w -> liftWaits.add(w * speed));
                for (Kind k : List.of(Kind.CORRIDOR, Kind.EDGE, Kind.NODE, Kind.ZONE)) {
                    t.stats().waits(k).forEach(w -> laneWaits.add(w * speed));
                }
                return null;
            });
            return new Row(n, reserved, contacts, standstills, longestStill, simSeconds / 3600, tasks.get(), failed.get(), doorWaits, liftWaits, laneWaits,
                    cpu, routes.get(), reserved ? traffic.requests() : 0, new ArrayList<>(log).stream().filter(l -> l.contains(" steps aside ")).count(), charges.get(),
                    lowestBattery, building.lines("rescue courier-").size());
        }
    }

    /**
     * The node the courier last passed, as it reports it: where its next order starts. A drive cut short (refused at
     * its decision point) returns while the AGV still drives there: its order ends first.
     */
    /**
     * What a courier keeps in hand beyond its next leg and the way from there back to the dock, percent (24 m at 0.5 %
     * a metre): what it may drive that the map's lanes do not say before it is at the dock. One step aside there and back
     * on the ring's longest lane between junctions (2 x 8 m: a refusal ends the leg, and the next is checked again) and
     * one room aside after a wait over the bound (2 x 3.7 m); waits cost nothing (the battery drains by the metre), backing
     * off a blocked lane is under a metre; a courier that ate into it is urgent on its way to the dock, neither displaced
     * by plain couriers nor asked to make way while a plain one can. More is the exception, which the staff's rescue shows.
     */
    static final double MARGIN_PERCENT = 12;
    /** Simulated seconds a courier rests after a failed drive before it parks out of the way or takes its next task. */
    static final double REST_AFTER_FAILURE_SECONDS = 10;
    /** Simulated seconds an empty courier stands before the staff swap its battery ({@link BatteryRescue}). */
    static final double RESCUE_AFTER_SECONDS = 300;

    /** Whether a courier other than this one holds the dock or waits for it. */
    private static boolean dockTaken(TrafficControl traffic, String robot) {
        return traffic.read(t -> t.needing(t.map().node(LobbyParking.DOCK)).stream().anyMatch(r -> !r.equals(robot)));
    }

    private static boolean batteryEmpty(RemoteAgv agv) {
        return agv.state().map(s -> s.batteryState() != null && !s.batteryState().charging() && s.batteryState().batteryCharge() <= 0).orElse(false);
    }

    private static double battery(RemoteAgv agv) {
        return agv.state().map(s -> s.batteryState() == null ? 100.0 : s.batteryState().batteryCharge()).orElse(100.0);
    }

    private static String where(RemoteAgv agv) {
        long deadline = System.nanoTime() + 120_000_000_000L;
        while (System.nanoTime() < deadline) {
            AgvState s = agv.state().orElseThrow();
            if (s.nodeStates().isEmpty() && s.edgeStates().isEmpty() && !s.driving()) {
                return s.lastNodeId();
            }
            sleep(20);
        }
        return agv.state().orElseThrow().lastNodeId();
    }

    /** Each edge unreserved: a ride as the AGV's edge action, the pharmacy's door passed with its edge action, else a drive. */
    private static boolean driveEdges(RemoteAgv agv, List<String> path) {
        List<RemoteAgv.EdgeAction> actions = edgeActions(path);
        for (int i = 1; i < path.size(); i++) {
            RemoteAgv.EdgeAction a = actions.get(i - 1);
            String door = pharmacyDoor(path.get(i - 1), path.get(i));
            boolean ok = a != null ? agv.traverse(path.get(i - 1), path.get(i), a.actionType(), a.parameters())
                    : door != null ? agv.traverse(path.get(i - 1), path.get(i), "passDoor", Map.of("doorId", door)) : agv.drive(path.get(i - 1), path.get(i));
            if (!ok) {
                return false;
            }
        }
        return true;
    }

    /** The ride between the lift's landings as the edge action {@code ride}; every other edge a plain drive (null). */
    static List<RemoteAgv.EdgeAction> edgeActions(List<String> path) {
        List<RemoteAgv.EdgeAction> actions = new ArrayList<>();
        for (int i = 1; i < path.size(); i++) {
            String a = path.get(i - 1);
            String b = path.get(i);
            boolean ride = HospitalFloor.liftLandingAt(a).isPresent() && HospitalFloor.liftLandingAt(b).isPresent();
            actions.add(ride ? new RemoteAgv.EdgeAction("ride", Map.of("liftId", HospitalFloor.liftLandingAt(a).get().lift())) : null);
        }
        return actions;
    }

    /** The controlled door between two waypoints, if the edge passes one (unreserved drives open it with passDoor). */
    private static String pharmacyDoor(String a, String b) {
        return HospitalFloor.CONTROLLED_DOORS.stream().filter(d -> List.of(a, b).contains(d.a()) && List.of(a, b).contains(d.b()))
                .map(d -> d.door()).findFirst().orElse(null);
    }

    private static String pick(List<String> xs, Random random) {
        return xs.get(random.nextInt(xs.size()));
    }

    /** A shortest path (in edges) on the traffic map. */
    static List<String> path(TrafficMap map, String from, String to) {
        Map<String, String> previous = new HashMap<>();
        Deque<String> open = new ArrayDeque<>(List.of(from));
        previous.put(from, from);
        while (!open.isEmpty()) {
            String x = open.poll();
            if (x.equals(to)) {
                break;
            }
            for (String y : map.neighbours(x).stream().sorted().toList()) {
                if (previous.putIfAbsent(y, x) == null) {
                    open.add(y);
                }
            }
        }
        List<String> path = new ArrayList<>();
        for (String x = to; !x.equals(from); x = previous.get(x)) {
            path.add(0, x);
        }
        path.add(0, from);
        return path;
    }

    private static long cpuNanos() {
        return ((com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean()).getProcessCpuTime();
    }

    private static void sleep(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
