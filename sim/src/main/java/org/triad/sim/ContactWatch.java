package org.triad.sim;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;

/**
 * Finds robots whose discs touch after a step. Steering keeps robots apart, so a contact means they met where
 * neither could give way (or one was pushed): worth a line in the building's log. Hysteresis keeps one
 * meeting one contact, however long they stay pressed together.
 */
final class ContactWatch {
    /** Gap, metres, at or below which two discs count as touching (dyn4j leaves a few mm of slop). */
    static final double TOUCH = 0.01;
    /** Gap, metres, a touching pair must open before it can be reported again. */
    static final double APART = 0.05;

    private final Set<String> touching = new HashSet<>();
    private final List<Contact> all = new CopyOnWriteArrayList<>();
    private final List<Consumer<Contact>> listeners = new CopyOnWriteArrayList<>();

    void listen(Consumer<Contact> l) {
        listeners.add(l);
    }

    List<Contact> all() {
        return List.copyOf(all);
    }

    List<Contact> check(List<Robot> robots, double time) {
        List<Contact> found = List.of();
        for (int i = 0; i < robots.size(); i++) {
            Robot a = robots.get(i);
            Vec2 pa = a.position();
            for (int j = i + 1; j < robots.size(); j++) {
                Robot b = robots.get(j);
                Vec2 pb = b.position();
                double gap = pa.distance(pb) - a.radius - b.radius;
                if (gap > APART) {
                    if (!touching.isEmpty()) {
                        touching.remove(a.name + "|" + b.name);
                    }
                    continue;
                }
                if (gap <= TOUCH && touching.add(a.name + "|" + b.name)) {
                    Contact c = new Contact(a.name, b.name, pa.plus(pb).times(0.5), time);
                    if (found.isEmpty()) {
                        found = new ArrayList<>();
                    }
                    found.add(c);
                    all.add(c);
                    listeners.forEach(l -> l.accept(c));
                }
            }
        }
        return found;
    }
}
