package org.triad.sim;

import java.util.Optional;

/**
 * A robot activity started without blocking (e.g. {@link Robot#startMoveTo(String)}), so that several
 * robots can act at once: it completes while the simulation is stepped.
 */
public final class PendingAction {
    private final Simulation sim;
    private ActionResult result;

    PendingAction(Simulation sim) {
        this.sim = sim;
    }

    public boolean isDone() {
        return result != null;
    }

    /** The result once done. */
    public Optional<ActionResult> result() {
        return Optional.ofNullable(result);
    }

    /**
     * Steps the simulation until the activity is done (other robots' activities progress meanwhile); when a
     * {@link SimulationClock} steps the simulation, waits for it instead.
     *
     * @throws IllegalStateException when called from inside a step (e.g. from a scripted event)
     */
    public ActionResult await() {
        java.util.Optional<SimulationClock> clock = sim.clock();
        if (clock.isPresent()) {
            return clock.get().await(this);
        }
        sim.requireNotStepping();
        while (result == null) {
            sim.step();
        }
        return result;
    }

    void complete(ActionResult r) {
        result = r;
        sim.clock().ifPresent(SimulationClock::activityEnded);
    }
}
