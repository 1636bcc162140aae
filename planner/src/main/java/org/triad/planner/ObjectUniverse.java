package org.triad.planner;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.Problem;
import org.triad.planner.pddl.TypedName;

/** Objects (domain constants, then problem objects, in declaration order) and their types. */
final class ObjectUniverse {
    final List<String> names = new ArrayList<>();
    final Map<String, Integer> ids = new HashMap<>();
    private final Map<String, Set<String>> ancestors = new HashMap<>();
    private final Map<List<String>, int[]> byType = new HashMap<>();
    private final List<Set<String>> objectTypes = new ArrayList<>();

    ObjectUniverse(Domain domain, Problem problem) {
        Map<String, List<String>> parents = new HashMap<>();
        for (TypedName t : domain.types()) parents.computeIfAbsent(t.name(), k -> new ArrayList<>()).addAll(t.types());
        for (TypedName t : domain.types()) ancestors(t.name(), parents, new LinkedHashSet<>());
        add(domain.constants(), parents);
        add(problem.objects(), parents);
    }

    private Set<String> ancestors(String type, Map<String, List<String>> parents, Set<String> visiting) {
        Set<String> known = ancestors.get(type);
        if (known != null) return known;
        if (!visiting.add(type)) throw new PlanningInputException("type hierarchy has a cycle through '" + type + "'");
        Set<String> out = new LinkedHashSet<>();
        out.add(type);
        out.add("object");
        for (String p : parents.getOrDefault(type, List.of())) {
            if (!p.equals(type)) out.addAll(ancestors(p, parents, visiting));
        }
        ancestors.put(type, out);
        return out;
    }

    private void add(List<TypedName> objects, Map<String, List<String>> parents) {
        for (TypedName o : objects) {
            Integer existing = ids.get(o.name());
            Set<String> types;
            if (existing == null) {
                ids.put(o.name(), names.size());
                names.add(o.name());
                types = new LinkedHashSet<>();
                objectTypes.add(types);
            } else {
                types = objectTypes.get(existing);
            }
            for (String t : o.types()) types.addAll(ancestors(t, parents, new LinkedHashSet<>()));
        }
    }

    int size() {
        return names.size();
    }

    int id(String name) {
        Integer id = ids.get(name);
        if (id == null) throw new PlanningInputException("unknown object '" + name + "'");
        return id;
    }

    /** Object ids of a type (or of any of several types, for {@code either}), ascending. */
    int[] ofTypes(List<String> types) {
        return byType.computeIfAbsent(types, k -> {
            List<Integer> out = new ArrayList<>();
            for (int i = 0; i < names.size(); i++) {
                for (String t : types) {
                    if (objectTypes.get(i).contains(t)) {
                        out.add(i);
                        break;
                    }
                }
            }
            return out.stream().mapToInt(Integer::intValue).toArray();
        });
    }

    boolean isOf(int object, List<String> types) {
        Set<String> own = objectTypes.get(object);
        for (String t : types) if (own.contains(t)) return true;
        return false;
    }
}
