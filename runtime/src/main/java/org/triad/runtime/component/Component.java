package org.triad.runtime.component;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Optional;

/**
 * A component of a C&amp;C architecture: a name, typed ports and, once part of a composition, a
 * parent. Ports are declared in constructors; the structure is frozen when the root is deployed on
 * a {@link Scheduler}.
 */
public abstract class Component {
    private final List<Port<?>> ports = new ArrayList<>();
    private String name;
    private ComposedComponent parent;
    private Scheduler scheduler;

    protected Component() {
        String simple = getClass().getSimpleName();
        this.name = simple.isEmpty() ? "component" : Character.toLowerCase(simple.charAt(0)) + simple.substring(1);
    }

    /** The instance name: the subcomponent name given by the parent, or a root's class name in lower camel case. */
    public final String name() {
        return name;
    }

    /** Dot-separated instance names from the root, e.g. {@code hospitalApp.core.planner}. */
    public final String path() {
        return parent == null ? name : parent.path() + "." + name;
    }

    public final Optional<ComposedComponent> parent() {
        return Optional.ofNullable(parent);
    }

    public final List<Port<?>> ports() {
        return Collections.unmodifiableList(ports);
    }

    /** The port with the given name. */
    public final Port<?> port(String portName) {
        return ports.stream().filter(p -> p.name().equals(portName)).findFirst()
                .orElseThrow(() -> new IllegalArgumentException(path() + " has no port '" + portName + "'"));
    }

    public final boolean isDeployed() {
        return scheduler != null;
    }

    protected final <T> InPort<T> inPort(String portName, Class<T> type) {
        return declare(new InPort<>(this, portName, type));
    }

    protected final <T> OutPort<T> outPort(String portName, Class<T> type) {
        return declare(new OutPort<>(this, portName, type));
    }

    private <P extends Port<?>> P declare(P port) {
        requireNotDeployed();
        for (Port<?> p : ports) {
            if (p.name().equals(port.name())) {
                throw new IllegalArgumentException(path() + " already has a port named '" + port.name() + "'");
            }
        }
        ports.add(port);
        return port;
    }

    /** The scheduler this component is deployed on; fails if there is none yet. */
    final Scheduler scheduler() {
        if (scheduler == null) {
            throw new IllegalStateException(path() + " is not deployed: deploy its root component on a Scheduler first");
        }
        return scheduler;
    }

    void deployOn(Scheduler s) {
        this.scheduler = s;
    }

    void adopt(ComposedComponent newParent, String newName) {
        if (parent != null) {
            throw new IllegalStateException(path() + " is already a subcomponent; it cannot also be '" + newName + "' of " + newParent.path());
        }
        if (scheduler != null) {
            throw new IllegalStateException(path() + " is already deployed; it cannot become a subcomponent");
        }
        requireIdentifier(newName, "subcomponent");
        this.parent = newParent;
        this.name = newName;
    }

    final void requireNotDeployed() {
        if (scheduler != null) {
            throw new IllegalStateException(path() + " is deployed: its structure can no longer change");
        }
    }

    static void requireIdentifier(String s, String what) {
        if (s == null || s.isEmpty() || !Character.isJavaIdentifierStart(s.charAt(0))
                || !s.chars().allMatch(Character::isJavaIdentifierPart)) {
            throw new IllegalArgumentException("'" + s + "' is not a valid " + what + " name");
        }
    }

    @Override
    public String toString() {
        return getClass().getSimpleName() + " " + path();
    }
}
