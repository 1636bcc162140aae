package org.triad.vda5050.master;

import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;

import org.triad.refarc.ActionRunner;
import org.triad.refarc.StateSource;
import org.triad.runtime.app.Atom;
import org.triad.runtime.app.DomainObject;
import org.triad.runtime.app.EnumValue;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.ActionSchema;
import org.triad.runtime.schema.AppSchema;
import org.triad.runtime.schema.Effect;
import org.triad.runtime.schema.Expr;
import org.triad.runtime.schema.PropertySchema;
import org.triad.runtime.schema.Transitions;
import org.triad.vda5050.protocol.AgvState;

/**
 * Any application's actors on a VDA 5050 AGV without hand-written code, for {@code ./triad run --robots vda5050:...}:
 * every action of the models is executed by the AGV by a fixed convention; where the robot is and what it
 * carries are read from the AGV's state before every plan (see {@link #currentState()}), and the rest of what
 * the models know of the world is tracked from a situation through the postconditions of the actions that succeeded.
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
    private final AppSchema schema;
    private final Transitions transitions;
    private final RemoteAgv agv;
    /** The robot's place property and load relation, read from the AGV's state; null when the models have none. */
    private final PropertySchema place;
    private final PropertySchema load;
    private State state;

    public ModelAgvActors(AppSchema schema, State initial, RemoteAgv agv) {
        this.schema = Objects.requireNonNull(schema, "schema");
        this.transitions = new Transitions(schema);
        this.place = placeProperty(schema);
        this.load = loadProperty(schema);
        this.state = Objects.requireNonNull(initial, "initial");
        this.agv = Objects.requireNonNull(agv, "agv");
    }

    /**
     * The state the next plan starts from: the tracked state corrected by what the AGV reports now. Its
     * {@code lastNodeId} is the value of the robot's place (the robot property without parameters that
     * an action with parameters {@code src} and {@code dst} sets to {@code dst}, e.g. {@code loc()}); its
     * loads are the robot's load relation (the Boolean robot property of one parameter that an action
     * named {@code pick} makes true, e.g. {@code carries(i)}: it holds exactly for the loadIds). So a
     * move that the AGV finished while master control could not see it (a broker outage) is not sent
     * again, and a second task on the same AGV starts where it stands, not where a situation file says.
     */
    @Override
    public synchronized State currentState() {
        Optional<AgvState> reported = agv.state();
        if (reported.isEmpty()) {
            return state;
        }
        State.Builder b = state.toBuilder();
        boolean changed = false;
        if (place != null && reported.get().lastNodeId() != null) {
            Optional<DomainObject> node = state.object(reported.get().lastNodeId());
            Atom at = Atom.of(place.actor(), place.name());
            if (node.isPresent() && !node.get().equals(state.valueOf(at).orElse(null))) {
                b.value(at, node.get());
                changed = true;
            }
        }
        if (load != null && reported.get().loads() != null) {
            Set<String> loads = new HashSet<>();
            reported.get().loads().forEach(l -> loads.add(l.loadId()));
            for (DomainObject o : state.objects().values()) {
                if (!schema.isSubtype(o.typeName(), load.params().get(0).type())) {
                    continue;
                }
                Atom carried = Atom.of(load.actor(), load.name(), o);
                if (state.holds(carried) != loads.contains(o.name())) {
                    b.value(carried, loads.contains(o.name()));
                    changed = true;
                }
            }
        }
        if (changed) {
            state = b.build();
        }
        return state;
    }

    private static PropertySchema placeProperty(AppSchema schema) {
        for (ActionSchema a : schema.actions()) {
            if (!a.actor().equals(schema.robot()) || a.params().stream().noneMatch(p -> p.name().equals("dst"))
                    || a.params().stream().noneMatch(p -> p.name().equals("src"))) {
                continue;
            }
            for (Effect e : a.effects()) {
                if (e.isAssignment() && e.call().args().isEmpty() && e.value() instanceof Expr.Var v && v.name().equals("dst")) {
                    return schema.property(e.call().actor(), e.call().property()).filter(p -> p.actor().equals(schema.robot())).orElse(null);
                }
            }
        }
        return null;
    }

    private static PropertySchema loadProperty(AppSchema schema) {
        for (ActionSchema a : schema.actions()) {
            if (!a.name().equals("pick")) {
                continue;
            }
            for (Effect e : a.effects()) {
                if (!e.isAssignment() && e.holds() && e.call().args().size() == 1) {
                    Optional<PropertySchema> p = schema.property(e.call().actor(), e.call().property());
                    if (p.isPresent() && p.get().actor().equals(schema.robot()) && p.get().isBoolean() && p.get().params().size() == 1) {
                        return p.get();
                    }
                }
            }
        }
        return null;
    }

    @Override
    public Optional<String> violatedPrecondition(GroundAction a, State now) {
        return transitions.violatedPrecondition(a, now);
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

    @Override
    public Optional<org.triad.runtime.app.Failure> failure(GroundAction action) {
        return agv.lastFailureWithCause();
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
