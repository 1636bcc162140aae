package org.triad.service.fleet;

import java.util.Optional;
import java.util.concurrent.atomic.AtomicInteger;

import org.triad.building.BuildingMember;
import org.triad.building.ModelRobot;
import org.triad.building.SharedWorld;
import org.triad.refarc.ActionRunner;
import org.triad.refarc.StateSource;
import org.triad.refarc.fleet.FleetRobot;
import org.triad.runtime.app.Failure;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.State;

/**
 * A robot of {@link DryRunFleet}: a {@link ModelRobot} in the fleet's one building (its actions do what
 * their postconditions say, on the shared world), with optional delay, failures and disappearance.
 */
final class DryRunRobot implements FleetRobot, StateSource, ActionRunner, BuildingMember {
    private final String name;
    private final ModelRobot world;
    private final long delayMillis;
    private final String failAction;
    private final int failCalls;
    /** Whether the injected failures are the building's congestion (jam=) rather than faults (fail=). */
    private final boolean jam;
    private final int goneAfter;
    private final AtomicInteger failed = new AtomicInteger();
    private final AtomicInteger executed = new AtomicInteger();
    private volatile String lastFailure;
    private volatile boolean lastCongested;
    /** The battery this robot reports (percent, never charging), or null for none: {@code dry:...,battery=P}. */
    private volatile org.triad.refarc.fleet.Battery battery;
    /** What each action it executes takes of the reported battery, percent ({@code dry:...,drain=D}): a robot running low while it works. */
    private volatile double drainPerAction;

    DryRunRobot(String name, ModelRobot body, long delayMillis, String failAction, int failCalls, boolean jam, int goneAfter) {
        this.jam = jam;
        this.name = name;
        this.world = body;
        this.delayMillis = delayMillis;
        this.failAction = failAction;
        this.failCalls = failCalls;
        this.goneAfter = goneAfter;
    }

    @Override
    public String name() {
        return name;
    }

    void reportBattery(double percent) {
        battery = new org.triad.refarc.fleet.Battery(percent, false);
    }

    void drainPerAction(double percent) {
        drainPerAction = percent;
    }

    @Override
    public Optional<org.triad.refarc.fleet.Battery> battery() {
        return Optional.ofNullable(battery);
    }

    @Override
    public SharedWorld world() {
        return world.world();
    }

    @Override
    public StateSource stateSource() {
        return this;
    }

    @Override
    public ActionRunner actionRunner() {
        return this;
    }

    @Override
    public State currentState() {
        if (gone()) {
            throw new IllegalStateException("robot " + name + " does not answer (connection lost)");
        }
        return world.currentState();
    }

    @Override
    public Optional<String> violatedPrecondition(GroundAction action, State now) {
        return world.violatedPrecondition(action, now);
    }

    @Override
    public boolean execute(GroundAction action) throws InterruptedException {
        lastFailure = null;
        lastCongested = false;
        if (gone()) {
            lastFailure = "robot " + name + " does not answer (connection lost)";
            return false;
        }
        if (delayMillis > 0) {
            Thread.sleep(delayMillis);
        }
        if (action.action().equals(failAction) && failed.get() < failCalls) {
            failed.incrementAndGet();
            lastFailure = jam ? "injected congestion " + failed.get() + " of " + failCalls + " (jam=" + failAction + "*" + failCalls + ")"
                    : "injected failure " + failed.get() + " of " + failCalls + " (fail=" + failAction + "*" + failCalls + ")";
            lastCongested = jam;
            return false;
        }
        if (!world.execute(action)) {
            lastFailure = world.failureReason(action).orElse(null);
            return false;
        }
        executed.incrementAndGet();
        org.triad.refarc.fleet.Battery b = battery;
        if (b != null && drainPerAction > 0) {
            battery = new org.triad.refarc.fleet.Battery(Math.max(0, b.charge() - drainPerAction), false);
        }
        return true;
    }

    @Override
    public Optional<String> failureReason(GroundAction action) {
        if (gone()) {
            return Optional.of("robot " + name + " does not answer (connection lost)");
        }
        return Optional.ofNullable(lastFailure);
    }

    @Override
    public Optional<Failure> failure(GroundAction action) {
        if (!gone() && lastCongested && lastFailure != null) {
            return Optional.of(Failure.congestion(lastFailure));
        }
        return failureReason(action).map(Failure::fault);
    }

    private boolean gone() {
        return goneAfter >= 0 && executed.get() >= goneAfter;
    }
}
