package org.triad.examples.hospital.vda5050;

import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CountDownLatch;

import org.triad.examples.hospital.HospitalBuilding;
import org.triad.examples.hospital.HospitalFloor;
import org.triad.sim.Battery;
import org.triad.vda5050.devices.DeviceLink;
import org.triad.vda5050.security.BrokerCredentials;
import org.triad.sim.SimulationClock;
import org.triad.runtime.app.LauncherWatch;
import org.triad.vda5050.mqtt.BrokerUnreachableException;

/**
 * One simulated hospital building with its couriers as VDA 5050 AGVs on a broker, in this process, until it is
 * stopped (SIGTERM or Ctrl-C: each reports OFFLINE and draws its {@code <serial>.png}; killed hard, the broker
 * publishes their last will CONNECTIONBROKEN). All couriers share one simulation and one clock
 * ({@link HospitalBuilding}): they drive at the same time in the same corridors, and every contact between two
 * of them is printed as a line {@code contact courier-1 courier-2 at (x, y) t=T s}. What {@code ./triad robot} runs:
 *
 * <pre>
 * java ... HospitalAgvMain --broker tcp://127.0.0.1:1883 [--serial courier-1 | --count N] [--speed 10|max] [--seed 42]
 *                          [--out DIR] [--close-fire-door-at SECONDS] [--battery PERCENT]
 *                          [--break-lift-at SECONDS] [--devices on|off] [--rescue-after SECONDS]
 * </pre>
 *
 * The building serves its doors and its lift on the broker ({@link BuildingDoors}, {@link BuildingLifts}); with
 * {@code --devices off} it does not (a building whose devices do not answer). {@code --break-lift-at T} makes the
 * lift stop between floors on its first ride after virtual time T. {@code --rescue-after S} has staff swap the battery of
 * a courier whose battery has been empty for S virtual seconds, where it stands, each printed as a line {@code rescue
 * courier-3 at c5 ...} ({@link BatteryRescue}); without it an empty courier stands for good.
 *
 * On a clean stop it prints how fast the building ran: {@code building: 600.0 s simulated in 60.0 s (10.00x real
 * time), CPU 12.3 s}.
 *
 * Exit code 2 for bad arguments or a broker that does not answer (one line naming host and port).
 */
public final class HospitalAgvMain {
    /**
     * @param serials          the AGVs' serial numbers
     * @param speed            virtual seconds per wall-clock second ({@code Double.POSITIVE_INFINITY}: as fast as the machine allows)
     * @param out              where each AGV draws its picture, or null
     * @param closeFireDoorAt  virtual time at which the fire door closes in every AGV's hospital, or null
     * @param battery          every courier's initial battery charge, percent
     * @param breakLiftAt      virtual time from which the lift stops between floors on its next ride, or null
     * @param devices          whether the building serves its doors and lift on the broker
     * @param rescueAfter      virtual seconds after which staff swap an empty courier's battery, or null (never)
     */
    public record Options(String broker, List<String> serials, long seed, double speed, Path out, Double closeFireDoorAt, double battery,
            Double breakLiftAt, boolean devices, Double rescueAfter) {
        public Options(String broker, List<String> serials, long seed, double speed, Path out, Double closeFireDoorAt, double battery,
                Double breakLiftAt, boolean devices) {
            this(broker, serials, seed, speed, out, closeFireDoorAt, battery, breakLiftAt, devices, null);
        }

        public Options(String broker, List<String> serials, long seed, double speed, Path out, Double closeFireDoorAt) {
            this(broker, serials, seed, speed, out, closeFireDoorAt, 100);
        }

        public Options(String broker, List<String> serials, long seed, double speed, Path out, Double closeFireDoorAt, double battery) {
            this(broker, serials, seed, speed, out, closeFireDoorAt, battery, null, true);
        }

        public Options {
            if (!(battery >= 0 && battery <= 100)) {
                throw new IllegalArgumentException("--battery takes a charge in percent 0..100, not " + battery);
            }
            if (broker == null) {
                throw new IllegalArgumentException("--broker tcp://HOST:PORT is required");
            }
            if (serials.isEmpty()) {
                throw new IllegalArgumentException("at least one robot is needed");
            }
            if (!(speed > 0)) {
                throw new IllegalArgumentException("--speed takes a positive factor or 'max', not " + speed);
            }
            if (closeFireDoorAt != null && (!(closeFireDoorAt >= 0) || closeFireDoorAt.isInfinite())) {
                throw new IllegalArgumentException("--close-fire-door-at takes a time in seconds >= 0, not " + closeFireDoorAt);
            }
            if (breakLiftAt != null && (!(breakLiftAt >= 0) || breakLiftAt.isInfinite())) {
                throw new IllegalArgumentException("--break-lift-at takes a time in seconds >= 0, not " + breakLiftAt);
            }
            if (rescueAfter != null && (!(rescueAfter >= 0) || rescueAfter.isInfinite())) {
                throw new IllegalArgumentException("--rescue-after takes a time in seconds >= 0, not " + rescueAfter);
            }
            serials = List.copyOf(serials);
        }

        /** Serial numbers {@code prefix-1} .. {@code prefix-count}. */
        public static List<String> numbered(String prefix, int count) {
            if (count < 1 || count > 1000) {
                throw new IllegalArgumentException("--count takes 1..1000, not " + count);
            }
            List<String> s = new ArrayList<>();
            for (int i = 1; i <= count; i++) {
                s.add(prefix + "-" + i);
            }
            return s;
        }
    }

    private HospitalAgvMain() {
    }

    /** CPU time of this process so far (all threads), nanoseconds; 0 where the JVM cannot tell. */
    static long cpuNanos() {
        java.lang.management.OperatingSystemMXBean os = java.lang.management.ManagementFactory.getOperatingSystemMXBean();
        return os instanceof com.sun.management.OperatingSystemMXBean sun ? sun.getProcessCpuTime() : 0;
    }

    public static void main(String[] args) {
        Options o;
        try {
            o = parse(args);
        } catch (IllegalArgumentException e) {
            System.err.println("triad robot: " + e.getMessage());
            System.exit(2);
            return;
        }
        // started by ./triad robot: end (reporting OFFLINE) when ./triad is gone, even if it was killed with SIGKILL
        LauncherWatch.exitWithLauncher(System.err::println);
        System.exit(serve(o, System.out, System.err));
    }

    static Options parse(String[] args) {
        String broker = null;
        String serial = null;
        Integer count = null;
        long seed = 42;
        double speed = 10;
        Path out = null;
        Double door = null;
        double battery = 100;
        Double breakLift = null;
        boolean devices = true;
        Double rescue = null;
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            if (i + 1 >= args.length) {
                throw new IllegalArgumentException("option " + a + " needs a value");
            }
            String v = args[++i];
            try {
                switch (a) {
                    case "--broker" -> broker = v;
                    case "--serial" -> serial = v;
                    case "--count" -> count = Integer.parseInt(v);
                    case "--seed" -> seed = Long.parseLong(v);
                    case "--speed" -> speed = v.equals("max") ? Double.POSITIVE_INFINITY : Double.parseDouble(v);
                    case "--out" -> out = Path.of(v);
                    case "--close-fire-door-at" -> door = Double.parseDouble(v);
                    case "--battery" -> battery = Double.parseDouble(v);
                    case "--break-lift-at" -> breakLift = Double.parseDouble(v);
                    case "--rescue-after" -> rescue = Double.parseDouble(v);
                    case "--devices" -> {
                        if (!v.equals("on") && !v.equals("off")) {
                            throw new IllegalArgumentException("--devices takes on or off, not '" + v + "'");
                        }
                        devices = v.equals("on");
                    }
                    default -> throw new IllegalArgumentException("unknown option " + a);
                }
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("option " + a + " takes a number, not '" + v + "'");
            }
        }
        if (serial != null && count != null) {
            throw new IllegalArgumentException("give --serial S or --count N (serials courier-1..N), not both");
        }
        List<String> serials = count != null ? Options.numbered("courier", count) : List.of(serial == null ? "courier-1" : serial);
        return new Options(broker, serials, seed, speed, out, door, battery, breakLift, devices, rescue);
    }

    /** Starts the building and its AGVs and serves until the JVM is stopped; returns 2 at once if the broker does not answer. */
    public static int serve(Options o, PrintStream out, PrintStream err) {
        List<SimulatedAgv> agvs = new java.util.concurrent.CopyOnWriteArrayList<>();
        HospitalBuilding building;
        try {
            if (o.out() != null) {
                Files.createDirectories(o.out());
            }
            // the trace (every frame) is only kept for the pictures: a long-running building would grow without bound
            building = new HospitalBuilding(o.seed(), o.out() != null, o.serials());
        } catch (IllegalArgumentException e) {
            err.println("triad robot: " + e.getMessage());
            return 2;
        } catch (java.io.IOException e) {
            err.println("triad robot: cannot create " + o.out() + ": " + e.getMessage());
            return 2;
        }
        for (HospitalBuilding.Courier c : building.couriers()) {
            Battery b = c.robot().battery();
            c.robot().setBattery(new Battery(b.capacityJoules(), b.joulesPerMetre(), b.chargingWatts(), o.battery() / 100));
        }
        if (o.closeFireDoorAt() != null) {
            building.sim().at(o.closeFireDoorAt()).closeDoor(HospitalFloor.FIRE_DOOR);
        }
        if (o.breakLiftAt() != null) {
            building.sim().at(o.breakLiftAt()).breakLift(HospitalFloor.LIFT);
        }
        building.onContact(c -> out.println(c));
        if (o.rescueAfter() != null) {
            BatteryRescue.serve(building, o.rescueAfter(), out::println);
        }
        long cpuStart = cpuNanos();
        SimulationClock clock = building.start(o.speed());
        java.util.concurrent.atomic.AtomicReference<DeviceLink> deviceLink = new java.util.concurrent.atomic.AtomicReference<>();
        CountDownLatch stopped = new CountDownLatch(1);
        // registered before the first AGV connects: stopped at any moment from now on, every AGV reports OFFLINE
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            agvs.forEach(SimulatedAgv::close);
            DeviceLink d = deviceLink.getAndSet(null);
            if (d != null) {
                d.close();
            }
            double simulated = clock.simulation().time();
            double ratio = clock.achievedSpeed();
            building.stop();
            out.printf(Locale.ROOT, "building: %.1f s simulated in %.1f s (%.2fx real time), CPU %.1f s%n", simulated,
                    ratio > 0 ? simulated / ratio : 0, ratio, (cpuNanos() - cpuStart) / 1e9);
            if (o.out() != null) {
                out.println("pictures written to " + o.out().toAbsolutePath().normalize());
            }
            stopped.countDown();
        }, "agv-shutdown"));
        String pace = Double.isInfinite(o.speed()) ? "as fast as possible" : String.format(Locale.ROOT, "%.0fx real time", o.speed());
        try {
            for (String serial : o.serials()) {
                SimulatedAgv agv = new SimulatedAgv(o.broker(), building, serial, o.out(), line -> out.println(line));
                agvs.add(agv.start());
                String at = clock.call(s -> building.floor().waypointAt(s.robot(serial).position()));
                out.printf(Locale.ROOT, "robot %s ONLINE on %s: VDA 5050 2.1.0, topics uagv/v2/triad/%s/*, %s, in the %s%n", serial,
                        o.broker(), serial, pace, at);
            }
        } catch (BrokerUnreachableException | IllegalArgumentException | IllegalStateException e) {
            err.println("triad robot: " + e.getMessage());
            agvs.forEach(SimulatedAgv::close);
            agvs.clear();
            building.stop();
            return 2;
        }
        if (!o.devices()) {
            out.println("devices: off (--devices off): the building's doors and lift answer no request");
        } else {
            try {
                // on a secured broker as the building's identity, the only one the ACL lets answer for a device
                deviceLink.set(DeviceLink.connect(o.broker(), BrokerCredentials.BUILDING, "triad-building-devices", line -> out.println(line)));
                BuildingDoors.serve(building, deviceLink.get());
                BuildingLifts.serve(building, deviceLink.get());
                out.println("devices: doors " + BuildingDoors.served(clock) + " answer requests on triad/devices/v1/doors/<name>/request, lifts "
                        + BuildingLifts.names(clock) + " on triad/devices/v1/lifts/<name>/request");
            } catch (BrokerUnreachableException | IllegalArgumentException | IllegalStateException e) {
                err.println("triad robot: " + e.getMessage());
                agvs.forEach(SimulatedAgv::close);
                agvs.clear();
                DeviceLink d = deviceLink.getAndSet(null);
                if (d != null) {
                    d.close();
                }
                building.stop();
                return 2;
            }
        }
        out.printf(Locale.ROOT, "building: one hospital, %d robot(s), one clock (%s)%n", agvs.size(), pace);
        try {
            stopped.await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return 0;
    }
}
