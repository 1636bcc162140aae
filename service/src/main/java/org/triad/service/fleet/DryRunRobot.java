package org.triad.service.fleet;

import java.util.Optional;
import java.util.concurrent.atomic.AtomicInteger;

import org.triad.refarc.ActionRunner;
import org.triad.refarc.StateSource;
import org.triad.refarc.fleet.FleetRobot;
import org.triad.refarc.model.DryRunWorld;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.AppSchema;

/** A robot of {@link DryRunFleet}: a {@link DryRunWorld} of its own, with optional delay, failures and disappearance. */
final class DryRunRobot implements FleetRobot, StateSource, ActionRunner {
    private final String name;
    private final DryRunWorld world;
    private final long delayMillis;
    private final String failAction;
    private final int failCalls;
    private final int goneAfter;
    private final AtomicInteger failed = new AtomicInteger();
    private final AtomicInteger executed = new AtomicInteger();

    DryRunRobot(String name, AppSchema schema, State initial, long delayMillis, String failAction, int failCalls, int goneAfter) {
        this.name = name;
        this.world = new DryRunWorld(schema, initial);
        this.delayMillis = delayMillis;
        this.failAction = failAction;
        this.failCalls = failCalls;
        this.goneAfter = goneAfter;
    }

    @Override
    public String name() {
        return name;
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
        if (gone()) {
            return false;
        }
        if (delayMillis > 0) {
            Thread.sleep(delayMillis);
        }
        if (action.action().equals(failAction) && failed.get() < failCalls) {
            failed.incrementAndGet();
            return false;
        }
        executed.incrementAndGet();
        return world.execute(action);
    }

    @Override
    public Optional<String> failureReason(GroundAction action) {
        if (gone()) {
            return Optional.of("robot " + name + " does not answer (connection lost)");
        }
        return action.action().equals(failAction) ? Optional.of("injected failure " + failed.get() + " of " + failCalls + " (fail=" + failAction + "*" + failCalls + ")")
                : Optional.empty();
    }

    private boolean gone() {
        return goneAfter >= 0 && executed.get() >= goneAfter;
    }
}
