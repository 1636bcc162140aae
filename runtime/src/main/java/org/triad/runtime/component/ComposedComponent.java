package org.triad.runtime.component;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * A component made of subcomponents and connectors. Its in ports forward to subcomponent in ports,
 * subcomponent out ports forward to its out ports. A connector starts at an out port of a
 * subcomponent or an in port of this component and ends at an in port of a subcomponent or an out
 * port of this component; every target has at most one sender and accepts the sender's type.
 *
 * <p>Every composed component has the in port {@link #faults}, fed by the runtime: when a handler
 * or activity of a descendant throws, the fault goes to the nearest enclosing composed component
 * that connects {@code faults} to a subcomponent (e.g. to put it on a Status port); if none does,
 * to the scheduler's fault listener.
 */
public abstract class ComposedComponent extends Component {
    /** The name of the runtime-fed fault port. */
    public static final String FAULTS = "faults";

    private final List<Component> subcomponents = new ArrayList<>();

    /** Faults raised in this component's subtree; connect it to route them. Nothing outside may send to it. */
    protected final InPort<ComponentFault> faults = inPort(FAULTS, ComponentFault.class);

    protected final <C extends Component> C subcomponent(String instanceName, C component) {
        requireNotDeployed();
        if (component == null) {
            throw new IllegalArgumentException("null subcomponent '" + instanceName + "' in " + path());
        }
        for (Component c : subcomponents) {
            if (c.name().equals(instanceName)) {
                throw new IllegalArgumentException(path() + " already has a subcomponent named '" + instanceName + "'");
            }
        }
        component.adopt(this, instanceName);
        subcomponents.add(component);
        return component;
    }

    public final List<Component> subcomponents() {
        return Collections.unmodifiableList(subcomponents);
    }

    /** Connects {@code from} to each of {@code to} (fan-out). */
    protected final void connect(Port<?> from, Port<?>... to) {
        requireNotDeployed();
        if (to.length == 0) {
            throw new IllegalArgumentException("a connector from " + from + " needs at least one target");
        }
        boolean fromOk = from.owner() == this ? from instanceof InPort : isSubcomponent(from.owner()) && from instanceof OutPort;
        if (!fromOk) {
            throw new IllegalArgumentException("a connector in " + path() + " cannot start at " + from
                    + ": it must start at an out port of a subcomponent or an in port of " + path());
        }
        Set<Port<?>> seen = new HashSet<>();
        for (Port<?> target : to) {
            if (!seen.add(target)) {
                throw new IllegalArgumentException("the connector from " + from.qualifiedName() + " names " + target.qualifiedName() + " twice");
            }
            boolean toOk = target.owner() == this ? target instanceof OutPort : isSubcomponent(target.owner()) && target instanceof InPort;
            if (!toOk) {
                throw new IllegalArgumentException("a connector in " + path() + " cannot end at " + target
                        + ": it must end at an in port of a subcomponent or an out port of " + path());
            }
            if (target.owner() instanceof ComposedComponent && target.name().equals(FAULTS) && target instanceof InPort) {
                throw new IllegalArgumentException(target + " is fed by the runtime; connectors cannot send to it");
            }
            // a port of a type parameter is erased to Object: the models were type-checked, and delivery checks each message
            if (!target.type().isAssignableFrom(from.type()) && from.type() != Object.class) {
                throw new IllegalArgumentException("type mismatch: " + from + " cannot send to " + target);
            }
            if (target.source().isPresent()) {
                throw new IllegalStateException(target + " already has the sender " + target.source().get().qualifiedName()
                        + "; cannot also connect " + from.qualifiedName());
            }
        }
        for (Port<?> target : to) {
            from.addTarget(target);
        }
    }

    private boolean isSubcomponent(Component c) {
        return c.parent().orElse(null) == this;
    }

    @Override
    void deployOn(Scheduler s) {
        super.deployOn(s);
        for (Component c : subcomponents) {
            c.deployOn(s);
        }
    }
}
