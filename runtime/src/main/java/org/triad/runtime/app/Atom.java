package org.triad.runtime.app;

import java.util.List;
import java.util.stream.Collectors;

/**
 * A property of an actor applied to arguments, e.g. {@code Building.adj(storage, ward3)} or
 * {@code Courier.loc()}. In a {@link State} an atom has a value: {@code true} for a Boolean property
 * that holds, or the property's value for other properties.
 */
public record Atom(String actor, String property, List<Object> args) {
    public Atom {
        args = args.stream().map(Values::canonical).toList();
    }

    public static Atom of(String actor, String property, Object... args) {
        return new Atom(actor, property, List.of(args));
    }

    @Override
    public String toString() {
        return actor + "." + property + "(" + args.stream().map(String::valueOf).collect(Collectors.joining(", ")) + ")";
    }
}
