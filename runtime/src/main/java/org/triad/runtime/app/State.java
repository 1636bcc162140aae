package org.triad.runtime.app;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.stream.Collectors;

/**
 * An immutable snapshot of the world: the objects that exist and the values of the actors'
 * properties. Closed world: a Boolean atom that is not stored is false; a non-Boolean atom that is
 * not stored has no value. Iteration order is insertion order, so everything derived from a state
 * (PDDL problems, plans) is deterministic.
 */
public final class State {
    private final Map<String, DomainObject> objects;
    private final Map<Atom, Object> values;

    private State(Map<String, DomainObject> objects, Map<Atom, Object> values) {
        this.objects = Collections.unmodifiableMap(objects);
        this.values = Collections.unmodifiableMap(values);
    }

    public static Builder builder() {
        return new Builder();
    }

    /** A builder initialised with this state's objects and values. */
    public Builder toBuilder() {
        Builder b = new Builder();
        b.objects.putAll(objects);
        b.values.putAll(values);
        return b;
    }

    /** The objects that exist, by name, in insertion order. */
    public Map<String, DomainObject> objects() {
        return objects;
    }

    public Optional<DomainObject> object(String name) {
        return Optional.ofNullable(objects.get(name));
    }

    /** The stored atoms and their values, in insertion order. */
    public Map<Atom, Object> values() {
        return values;
    }

    /** Whether a Boolean atom holds (closed world). */
    public boolean holds(Atom atom) {
        return Boolean.TRUE.equals(values.get(atom));
    }

    /** The value of a non-Boolean atom, if it has one. */
    public Optional<Object> valueOf(Atom atom) {
        return Optional.ofNullable(values.get(atom));
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof State s && s.objects.equals(objects) && s.values.equals(values);
    }

    @Override
    public int hashCode() {
        return objects.hashCode() * 31 + values.hashCode();
    }

    @Override
    public String toString() {
        return "objects " + objects.values().stream().map(o -> o.name() + ":" + o.typeName()).collect(Collectors.joining(", "))
                + "; " + values.entrySet().stream()
                        .map(e -> Boolean.TRUE.equals(e.getValue()) ? e.getKey().toString() : e.getKey() + " == " + e.getValue())
                        .collect(Collectors.joining(", "));
    }

    /** Collects objects and atom values; later values of the same atom replace earlier ones. */
    public static final class Builder {
        private final Map<String, DomainObject> objects = new LinkedHashMap<>();
        private final Map<Atom, Object> values = new LinkedHashMap<>();

        private Builder() {
        }

        public Builder object(DomainObject o) {
            DomainObject previous = objects.putIfAbsent(o.name(), o);
            if (previous != null && !previous.equals(o)) {
                throw new IllegalArgumentException("two objects named '" + o.name() + "': " + previous.typeName() + " and " + o.typeName());
            }
            return this;
        }

        public Builder objects(Iterable<? extends DomainObject> os) {
            os.forEach(this::object);
            return this;
        }

        /** Makes a Boolean atom hold. */
        public Builder fact(Atom atom) {
            values.put(atom, Boolean.TRUE);
            return this;
        }

        /** Makes a Boolean atom false (removes it, closed world). */
        public Builder retract(Atom atom) {
            values.remove(atom);
            return this;
        }

        /** Sets the value of an atom; {@code Boolean.FALSE} or {@code null} removes it. */
        public Builder value(Atom atom, Object value) {
            if (value == null || Boolean.FALSE.equals(value)) {
                values.remove(atom);
            } else {
                values.put(atom, Values.canonical(value));
            }
            return this;
        }

        public Builder facts(List<Atom> atoms) {
            atoms.forEach(this::fact);
            return this;
        }

        public State build() {
            return new State(new LinkedHashMap<>(objects), new LinkedHashMap<>(values));
        }
    }
}
