package org.triad.examples.hospital.vda5050;

import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CountDownLatch;

import org.triad.examples.hospital.HospitalFloor;
import org.triad.runtime.app.LauncherWatch;
import org.triad.vda5050.mqtt.BrokerUnreachableException;

/**
 * Simulated hospital couriers as VDA 5050 AGVs on a broker, in this process, until it is stopped (SIGTERM
 * or Ctrl-C: each reports OFFLINE and draws its {@code <serial>.png}; killed hard, the broker publishes
 * their last will CONNECTIONBROKEN). What {@code ./triad robot} runs:
 *
 * <pre>
 * java ... HospitalAgvMain --broker tcp://127.0.0.1:1883 [--serial courier-1 | --count N] [--speed 10] [--seed 42]
 *                          [--out DIR] [--close-fire-door-at SECONDS]
 * </pre>
 *
 * Exit code 2 for bad arguments or a broker that does not answer (one line naming host and port).
 */
public final class HospitalAgvMain {
    /**
     * @param serials          the AGVs' serial numbers
     * @param speed            virtual seconds per wall-clock second
     * @param out              where each AGV draws its picture, or null
     * @param closeFireDoorAt  virtual time at which the fire door closes in every AGV's hospital, or null
     */
    public record Options(String broker, List<String> serials, long seed, double speed, Path out, Double closeFireDoorAt) {
        public Options {
            if (broker == null) {
                throw new IllegalArgumentException("--broker tcp://HOST:PORT is required");
            }
            if (serials.isEmpty()) {
                throw new IllegalArgumentException("at least one robot is needed");
            }
            if (!(speed > 0) || Double.isInfinite(speed)) {
                throw new IllegalArgumentException("--speed takes a positive factor, not " + speed);
            }
            if (closeFireDoorAt != null && (!(closeFireDoorAt >= 0) || closeFireDoorAt.isInfinite())) {
                throw new IllegalArgumentException("--close-fire-door-at takes a time in seconds >= 0, not " + closeFireDoorAt);
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
                    case "--speed" -> speed = Double.parseDouble(v);
                    case "--out" -> out = Path.of(v);
                    case "--close-fire-door-at" -> door = Double.parseDouble(v);
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
        return new Options(broker, serials, seed, speed, out, door);
    }

    /** Starts the AGVs and serves until the JVM is stopped; returns 2 at once if the broker does not answer. */
    public static int serve(Options o, PrintStream out, PrintStream err) {
        List<SimulatedAgv> agvs = new ArrayList<>();
        try {
            if (o.out() != null) {
                Files.createDirectories(o.out());
            }
            for (String serial : o.serials()) {
                SimulatedAgv agv = new SimulatedAgv(o.broker(), serial, o.seed(), o.speed(), o.out(), line -> out.println(line));
                if (o.closeFireDoorAt() != null) {
                    agv.hospital().sim().at(o.closeFireDoorAt()).closeDoor(HospitalFloor.FIRE_DOOR);
                }
                agvs.add(agv.start());
                out.printf(Locale.ROOT, "robot %s ONLINE on %s: VDA 5050 2.1.0, topics uagv/v2/triad/%s/*, %.0fx real time, in the lobby%n", serial,
                        o.broker(), serial, o.speed());
            }
        } catch (BrokerUnreachableException | IllegalArgumentException | IllegalStateException e) {
            err.println("triad robot: " + e.getMessage());
            agvs.forEach(SimulatedAgv::close);
            return 2;
        } catch (java.io.IOException e) {
            err.println("triad robot: cannot create " + o.out() + ": " + e.getMessage());
            return 2;
        }
        CountDownLatch stopped = new CountDownLatch(1);
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            agvs.forEach(SimulatedAgv::close);
            if (o.out() != null) {
                out.println("pictures written to " + o.out().toAbsolutePath().normalize());
            }
            stopped.countDown();
        }, "agv-shutdown"));
        try {
            stopped.await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return 0;
    }
}
