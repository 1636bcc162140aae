package org.triad.building;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;

import org.triad.refarc.ActionRunner;
import org.triad.refarc.StateSource;
import org.triad.runtime.app.Atom;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.Transitions;

/**
 * A robot of a {@link SharedWorld} without a platform: its own robot-actor values (it starts where the
 * situation puts the robot), and actions that do exactly what their postconditions say, on the shared
 * world. An action is checked and applied as one step of the building, so of two robots reaching for
 * the same item at the same moment one gets it and the other's action fails with the reason.
 */
public final class ModelRobot implements StateSource, ActionRunner {
    private final SharedWorld world;
    private final String name;
    private final Transitions transitions;
    private final Map<Atom, Object> own = new LinkedHashMap<>();
    private volatile String lastFailure;

    ModelRobot(SharedWorld world, String name, Map<Atom, Object> start) {
        this.world = world;
        this.name = name;
        this.transitions = new Transitions(world.schema());
        own.putAll(start);
    }

    public String name() {
        return name;
    }

    public SharedWorld world() {
        return world;
    }

    private State ownState() {
        synchronized (own) {
            State.Builder b = State.builder();
            own.forEach(b::value);
            return b.build();
        }
    }

    @Override
    public State currentState() {
        return world.stateFor(ownState());
    }

    @Override
    public Optional<String> violatedPrecondition(GroundAction a, State now) {
        return transitions.violatedPrecondition(a, now);
    }

    @Override
    public boolean execute(GroundAction a) {
        return world.atomically(w -> {
            State now = world.stateFor(ownState());
            Optional<String> violated = violatedPrecondition(a, now);
            if (violated.isPresent()) {
                lastFailure = violated.get() + " any more: the building changed (another robot acted) since it was planned";
                return false;
            }
            State next = transitions.apply(a, now);
            world.replaceWorld(next);
            synchronized (own) {
                own.clear();
                next.values().forEach((atom, v) -> {
                    if (!world.isWorld(atom)) {
                        own.put(atom, v);
                    }
                });
            }
            lastFailure = null;
            return true;
        });
    }

    @Override
    public Optional<String> failureReason(GroundAction action) {
        return Optional.ofNullable(lastFailure);
    }
}
