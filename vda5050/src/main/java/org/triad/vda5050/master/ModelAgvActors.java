package org.triad.vda5050.master;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;

import org.triad.refarc.ActionRunner;
import org.triad.refarc.StateSource;
import org.triad.runtime.app.DomainObject;
import org.triad.runtime.app.EnumValue;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.ActionSchema;
import org.triad.runtime.schema.AppSchema;
import org.triad.runtime.schema.Exprs;
import org.triad.runtime.schema.ModelEvaluationException;
import org.triad.runtime.schema.Transitions;

/**
 * Any application's actors on a VDA 5050 AGV without hand-written code, for {@code ./triad run --robots vda5050:...}:
 * every action of the models is executed by the AGV by a fixed convention, and what the models know of the
 * world is tracked from a situation through the postconditions of the actions that succeeded.
 * <ul>
 * <li>an action with parameters {@code src} and {@code dst}: {@code move} is an order driving the edge
 * src-dst; any other such action drives that edge with an edge action of the action's name carrying the
 * other arguments (e.g. {@code guide(p, src, dst)});</li>
 * <li>any other action: an order of one node, where the AGV stands, with a node action of the action's name
 * and the arguments as actionParameters named after the model's parameters (objects by name).</li>
 * </ul>
 * The hospital's hand-written binding ({@code models/hospital}, package {@code vda5050}) shows the other way:
 * the generated {@code IRobot}/{@code IWorld} implemented on {@link RemoteAgv}, properties read from the AGV's state.
 */
public final class ModelAgvActors implements StateSource, ActionRunner {
    private final Transitions transitions;
    private final RemoteAgv agv;
    private State state;

    public ModelAgvActors(AppSchema schema, State initial, RemoteAgv agv) {
        this.transitions = new Transitions(Objects.requireNonNull(schema, "schema"));
        this.state = Objects.requireNonNull(initial, "initial");
        this.agv = Objects.requireNonNull(agv, "agv");
    }

    @Override
    public synchronized State currentState() {
        return state;
    }

    @Override
    public Optional<String> violatedPrecondition(GroundAction a, State now) {
        try {
            return transitions.isApplicable(a, now) ? Optional.empty()
                    : Optional.of("precondition " + Exprs.show(transitions.schemaOf(a).pre()) + " does not hold");
        } catch (ModelEvaluationException e) {
            return Optional.of(e.getMessage());
        }
    }

    @Override
    public boolean execute(GroundAction a) {
        ActionSchema s = transitions.schemaOf(a);
        Map<String, Object> args = new LinkedHashMap<>();
        transitions.binding(s, a).forEach((k, v) -> args.put(k, parameterValue(v)));
        boolean ok;
        if (args.containsKey("src") && args.containsKey("dst")) {
            String src = String.valueOf(args.remove("src"));
            String dst = String.valueOf(args.remove("dst"));
            ok = a.action().equals("move") ? agv.drive(src, dst) : agv.traverse(src, dst, a.action(), args);
        } else {
            String node = agv.state().map(st -> st.lastNodeId()).orElse("");
            ok = agv.nodeAction(node, a.action(), args);
        }
        if (ok) {
            synchronized (this) {
                state = transitions.apply(a, state);
            }
        }
        return ok;
    }

    @Override
    public Optional<String> failureReason(GroundAction action) {
        return agv.lastFailure();
    }

    /** Objects go by name, enumeration literals by literal, numbers, strings and Booleans as they are. */
    static Object parameterValue(Object v) {
        if (v instanceof DomainObject o) {
            return o.name();
        }
        if (v instanceof EnumValue e) {
            return e.literal();
        }
        if (v instanceof List<?> l) {
            return l.stream().map(ModelAgvActors::parameterValue).toList();
        }
        return v;
    }
}
