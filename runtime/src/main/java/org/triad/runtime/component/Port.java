package org.triad.runtime.component;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Optional;

/**
 * A typed port of a component. Connectors form a directed graph over ports: each port has at most
 * one sender ({@link #source()}) and any number of receivers ({@link #targets()}). The graph is
 * frozen when the root component is deployed on a {@link Scheduler}.
 *
 * @param <T> the type of the messages the port carries
 */
public abstract sealed class Port<T> permits InPort, OutPort {
    private final Component owner;
    private final String name;
    private final Class<T> type;
    private final List<Port<?>> targets = new ArrayList<>();
    private Port<?> source;

    Port(Component owner, String name, Class<T> type) {
        if (owner == null) {
            throw new IllegalArgumentException("a port needs an owning component");
        }
        Component.requireIdentifier(name, "port");
        if (type == null) {
            throw new IllegalArgumentException("port '" + name + "' needs a message type");
        }
        if (type.isPrimitive()) {
            throw new IllegalArgumentException("port '" + name + "' has primitive type " + type + ": use its wrapper class");
        }
        this.owner = owner;
        this.name = name;
        this.type = type;
    }

    public final Component owner() {
        return owner;
    }

    public final String name() {
        return name;
    }

    /** The declared message type; every message on this port is an instance of it. */
    public final Class<T> type() {
        return type;
    }

    /** The owner's path and the port name, e.g. {@code refArc.controller.task}. */
    public final String qualifiedName() {
        return owner.path() + "." + name;
    }

    /** The ports this port forwards its messages to, in connection order. */
    public final List<Port<?>> targets() {
        return Collections.unmodifiableList(targets);
    }

    /** The port that sends to this one, if it is connected. */
    public final Optional<Port<?>> source() {
        return Optional.ofNullable(source);
    }

    abstract String direction();

    void addTarget(Port<?> target) {
        targets.add(target);
        target.source = this;
    }

    @Override
    public String toString() {
        return direction() + " port " + qualifiedName() + " : " + type.getSimpleName();
    }
}
