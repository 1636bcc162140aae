package org.triad.planner.pddl;

import java.util.List;

/**
 * A name with its type: a parameter, object, constant or type declaration. {@code types} has one
 * element for a plain type and several for {@code (either t1 t2)}.
 */
public record TypedName(String name, List<String> types) {
    public TypedName {
        types = List.copyOf(types);
        if (types.isEmpty()) throw new IllegalArgumentException("a typed name needs at least one type: " + name);
    }

    public static TypedName of(String name, String type) {
        return new TypedName(name, List.of(type));
    }
}
