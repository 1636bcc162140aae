package org.triad.examples.hospital.fleet;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.atomic.AtomicInteger;

import org.triad.examples.hospital.vda5050.VdaHospital;
import org.triad.refarc.ActionRunner;
import org.triad.refarc.StateSource;
import org.triad.refarc.fleet.FleetContext;
import org.triad.refarc.fleet.FleetRobot;
import org.triad.refarc.fleet.RobotPlatformProvider;
import org.triad.vda5050.master.MasterControl;
import org.triad.vda5050.master.VdaTimeouts;
import org.triad.vda5050.protocol.Messages.ConnectionState;

import generated.hospital.HospitalActionExecutor;
import generated.hospital.HospitalStateProvider;

/**
 * Scheme {@code vda5050} of the hospital application: {@code vda5050:tcp://HOST:PORT[,wait=S]} drives
 * every hospital courier (manufacturer {@code triad}) that is ONLINE on that broker, found on the
 * {@code connection} topic within S seconds (default 2), through one {@link MasterControl}. Each is a
 * robot of the fleet named after its serial number, whose state is what the AGV reports (its last node,
 * its loads) and whose actions are VDA 5050 orders ({@code ./triad robot --broker URL --count N} starts
 * such AGVs).
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
        return "vda5050:tcp://HOST:PORT[,wait=S]  the hospital couriers ONLINE on that VDA 5050 broker";
    }

    @Override
    public List<FleetRobot> connect(String argument, FleetContext context) throws Exception {
        String[] parts = argument.split(",");
        String broker = parts[0].trim();
        double wait = DEFAULT_WAIT_SECONDS;
        for (int i = 1; i < parts.length; i++) {
            String[] kv = parts[i].split("=", 2);
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
        MasterControl master = MasterControl.connect(broker, VdaTimeouts.defaults(), line -> System.err.println("triad serve: " + line));
        long deadline = System.nanoTime() + (long) (wait * 1e9);
        while (System.nanoTime() < deadline) {
            Thread.sleep(50);
        }
        Map<String, ConnectionState> online = new TreeMap<>();
        master.announced().forEach((agv, state) -> {
            if (agv.startsWith(MasterControl.TRIAD + "/") && state == ConnectionState.ONLINE) {
                online.put(agv.substring(MasterControl.TRIAD.length() + 1), state);
            }
        });
        if (online.isEmpty()) {
            master.close();
            throw new IllegalStateException("no hospital courier (manufacturer '" + MasterControl.TRIAD + "') announced itself ONLINE on " + broker
                    + " within " + wait + " s (topic uagv/v2/" + MasterControl.TRIAD + "/+/connection); start them with './triad robot --broker "
                    + broker + " --count N'");
        }
        AtomicInteger open = new AtomicInteger(online.size());
        List<FleetRobot> robots = new ArrayList<>();
        for (String serial : online.keySet()) {
            robots.add(new Courier(serial, new VdaHospital(master, serial), () -> {
                if (open.decrementAndGet() == 0) {
                    master.close();
                }
            }));
        }
        return robots;
    }

    /** One AGV as a robot of the fleet: the generated StateProvider and ActionExecutor over the VDA 5050 binding. */
    private static final class Courier implements FleetRobot {
        private final String name;
        private final StateSource state;
        private final ActionRunner actions;
        private final Runnable onClose;

        Courier(String name, VdaHospital agv, Runnable onClose) {
            this.name = name;
            this.onClose = onClose;
            this.state = new HospitalStateProvider(agv.courier(), agv.building());
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
        public void close() {
            onClose.run();
        }
    }
}
