package org.triad.building;

import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import org.triad.runtime.app.DomainObject;
import org.triad.runtime.schema.AppSchema;
import org.triad.runtime.schema.Param;
import org.triad.runtime.schema.PropertySchema;
import org.triad.runtime.schema.TaskSchema;

/**
 * Which running task holds which objects of the building. A task claims the objects its arguments
 * name that are not places; a place is a type that some property takes as its value (a robot's
 * {@code loc()}, a person's {@code personAt(p)}: waypoints and rooms), with its subtypes. So
 * {@code CollectAndDeliver(gauze, storage, ward1)} claims {@code gauze}, {@code Guide(alice, ward1)}
 * claims {@code alice}, and {@code GoTo(ward1)} claims nothing: many robots may drive to one room,
 * but one item is carried by one robot. The dispatcher starts a task only when none of its objects is
 * held by another running task. Thread-safe.
 */
public final class Claims {
    /** An object and the running task (and its robot) that holds it. */
    public record Holder(String object, long task, String robot) {
        public String describe() {
            return object + ", held by task " + task + " on " + robot;
        }
    }

    private final AppSchema schema;
    private final Set<String> places = new LinkedHashSet<>();
    private final Map<Long, Set<String>> byTask = new LinkedHashMap<>();
    private final Map<Long, String> robotOf = new LinkedHashMap<>();

    public Claims(AppSchema schema) {
        this.schema = schema;
        for (PropertySchema p : schema.properties()) {
            if (!p.isBoolean() && schema.types().containsKey(p.type())) {
                for (String t : schema.types().keySet()) {
                    if (schema.isSubtype(t, p.type())) {
                        places.add(t);
                    }
                }
            }
        }
    }

    /** The types whose objects are places (never claimed). */
    public Set<String> places() {
        return Set.copyOf(places);
    }

    /** The objects a call of {@code task} with these argument values claims, by name, in argument order. */
    public Set<String> claimedBy(String task, List<Object> values) {
        TaskSchema t = schema.task(task).orElseThrow(() -> new IllegalArgumentException("no task '" + task + "'"));
        Set<String> out = new LinkedHashSet<>();
        for (int i = 0; i < t.params().size() && i < values.size(); i++) {
            Param p = t.params().get(i);
            Object v = values.get(i);
            if (v instanceof DomainObject o && schema.types().containsKey(p.type()) && !places.contains(o.typeName()) && !places.contains(p.type())) {
                out.add(o.name());
            }
        }
        return out;
    }

    /** The first of these objects that a task other than {@code task} holds, if any. */
    public synchronized Optional<Holder> holder(long task, Collection<String> objects) {
        for (Map.Entry<Long, Set<String>> e : byTask.entrySet()) {
            if (e.getKey() == task) {
                continue;
            }
            for (String o : objects) {
                if (e.getValue().contains(o)) {
                    return Optional.of(new Holder(o, e.getKey(), robotOf.get(e.getKey())));
                }
            }
        }
        return Optional.empty();
    }

    /** {@code task}, running on {@code robot}, holds these objects until {@link #release}. */
    public synchronized void take(long task, String robot, Collection<String> objects) {
        Optional<Holder> h = holder(task, objects);
        if (h.isPresent()) {
            throw new IllegalStateException("task " + task + " cannot take " + h.get().describe());
        }
        byTask.put(task, new LinkedHashSet<>(objects));
        robotOf.put(task, robot);
    }

    /** The task ended: its objects are free. */
    public synchronized void release(long task) {
        byTask.remove(task);
        robotOf.remove(task);
    }

    /** Every object held now, with its holder. */
    public synchronized List<Holder> held() {
        List<Holder> out = new ArrayList<>();
        byTask.forEach((t, os) -> os.forEach(o -> out.add(new Holder(o, t, robotOf.get(t)))));
        return out;
    }
}
