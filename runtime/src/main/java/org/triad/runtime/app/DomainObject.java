package org.triad.runtime.app;

import java.util.Objects;

/**
 * An object of an application's domain (an instance of a class of the class diagram). Generated
 * domain classes extend it. Objects are identified by their name within their most specific type,
 * because planners and situations refer to objects by name.
 */
public abstract class DomainObject {
    private final String name;

    protected DomainObject(String name) {
        if (name == null || name.isBlank()) {
            throw new IllegalArgumentException("a domain object needs a non-empty name");
        }
        this.name = name;
    }

    public final String name() {
        return name;
    }

    /** The name of this object's class in the class diagram. */
    public abstract String typeName();

    /**
     * The value of one of its class's attributes (declared in its class or a superclass), for models that
     * read it ({@code i.weight}); null when the object has no such attribute or it is unset. Generated
     * domain classes answer from their fields.
     */
    public Object attribute(String attribute) {
        return null;
    }

    @Override
    public final boolean equals(Object o) {
        return o instanceof DomainObject other && other.typeName().equals(typeName()) && other.name.equals(name);
    }

    @Override
    public final int hashCode() {
        return Objects.hash(typeName(), name);
    }

    @Override
    public String toString() {
        return name;
    }
}
