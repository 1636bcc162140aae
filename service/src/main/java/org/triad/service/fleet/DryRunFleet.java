package org.triad.service.fleet;

import java.util.ArrayList;
import java.util.List;

import org.triad.building.BuildingContext;
import org.triad.building.SharedWorld;
import org.triad.refarc.fleet.FleetContext;
import org.triad.refarc.fleet.FleetRobot;
import org.triad.refarc.fleet.RobotPlatformProvider;
import org.triad.runtime.app.State;

/**
 * Scheme {@code dry}, for every application: robots whose actions do exactly what their
 * postconditions say, in the fleet's one building (a {@link SharedWorld}: what one robot picks up is
 * gone for the others), like {@code ./triad run}. Argument
 * {@code N[,state=S][,delay=MS][,fail=ACTION*K|jam=ACTION*K][,gone=K][,battery=P[,drain=D]]} (a battery reported at P percent, for the charging policy, less D percent per action executed): N robots starting where situation S puts the
 * robot (default: the service's situation), each action taking MS milliseconds, the first K calls of
 * ACTION failing on every robot (with {@code jam}: as the building's congestion, as traffic control's
 * refusals and waits over the bound end a drive, so that the service queues the task again), or every robot vanishing (its state can no longer be read) after K actions.
 */
public final class DryRunFleet implements RobotPlatformProvider {
    public static final int MAX_ROBOTS = 1000;
    /** Robots are numbered across all {@code dry:} specs of one service, so that their names stay unique. */
    private int numbered;

    @Override
    public String application() {
        return ANY_APPLICATION;
    }

    @Override
    public String scheme() {
        return "dry";
    }

    @Override
    public String usage() {
        return "dry:N[,state=S][,delay=MS][,fail=ACTION*K|jam=ACTION*K][,gone=K][,battery=P[,drain=D]]  N robots that do what the postconditions say, over a situation";
    }

    @Override
    public List<FleetRobot> connect(String argument, FleetContext context) {
        String[] parts = argument.split(",");
        int n = number("dry:N", parts[0], 1, MAX_ROBOTS);
        String situation = null;
        long delayMillis = 0;
        String failAction = null;
        int failCalls = 0;
        boolean jam = false;
        int goneAfter = -1;
        int battery = -1;
        int drain = 0;
        for (int i = 1; i < parts.length; i++) {
            String[] kv = parts[i].split("=", 2);
            if (kv.length != 2) {
                throw new IllegalArgumentException("dry: expected KEY=VALUE, not '" + parts[i] + "'; " + usage());
            }
            String value = kv[1].trim();
            switch (kv[0].trim()) {
                case "state" -> situation = value;
                case "delay" -> delayMillis = number("dry:...,delay=MS", value, 0, 600_000);
                case "gone" -> goneAfter = number("dry:...,gone=K", value, 0, Integer.MAX_VALUE);
                case "battery" -> battery = number("dry:...,battery=PERCENT", value, 0, 100);
                case "drain" -> drain = number("dry:...,drain=PERCENT", value, 0, 100);
                case "fail", "jam" -> {
                    String key = kv[0].trim();
                    if (failAction != null) {
                        throw new IllegalArgumentException("dry: one of fail= and jam= per robot spec, not both; " + usage());
                    }
                    jam = key.equals("jam");
                    String[] ak = value.split("\\*", 2);
                    failAction = ak[0].trim();
                    failCalls = ak.length == 2 ? number("dry:...," + key + "=ACTION*K", ak[1], 1, Integer.MAX_VALUE) : 1;
                    String action = failAction;
                    if (context.schema().actions().stream().noneMatch(a -> a.name().equals(action))) {
                        throw new IllegalArgumentException("dry:...," + key + "=" + value + ": the application has no action '" + action + "'");
                    }
                }
                default -> throw new IllegalArgumentException("dry: unknown option '" + kv[0] + "'; " + usage());
            }
        }
        State initial = context.situation(situation);
        // one building for the whole fleet: the service's, or one for these robots when used without a service
        SharedWorld world = context instanceof BuildingContext b ? b.world() : new SharedWorld(context.schema(), initial);
        if (situation != null) {
            world.startAs(initial); // the first word on the building's world wins; later specs' robots start where S puts them
        }
        List<FleetRobot> robots = new ArrayList<>();
        for (int i = 1; i <= n; i++) {
            String name = "dry-" + ++numbered;
            DryRunRobot r = new DryRunRobot(name, world.modelRobot(name, initial), delayMillis, failAction, failCalls, jam, goneAfter);
            if (battery >= 0) {
                r.reportBattery(battery);
                r.drainPerAction(drain);
            } else if (drain > 0) {
                throw new IllegalArgumentException("dry:...,drain=" + drain + " drains a reported battery: give it one with battery=PERCENT");
            }
            robots.add(r);
        }
        return robots;
    }

    private static int number(String what, String text, int min, int max) {
        int v;
        try {
            v = Integer.parseInt(text.trim());
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(what + " takes a whole number, not '" + text + "'");
        }
        if (v < min || v > max) {
            throw new IllegalArgumentException(what + " takes " + min + " to " + max + ", not " + v);
        }
        return v;
    }
}
