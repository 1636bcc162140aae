package org.triad.sim;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/** Recorded history of a simulation: one {@link TraceFrame} per step and the {@link TraceEvent}s. */
public final class Trace {
    private final List<String> robotNames = new ArrayList<>();
    private final List<String> personNames = new ArrayList<>();
    private final List<String> itemNames = new ArrayList<>();
    private final List<TraceFrame> frames = new ArrayList<>();
    private final List<TraceEvent> events = new ArrayList<>();

    public List<String> robotNames() {
        return Collections.unmodifiableList(robotNames);
    }

    public List<String> personNames() {
        return Collections.unmodifiableList(personNames);
    }

    public List<String> itemNames() {
        return Collections.unmodifiableList(itemNames);
    }

    public List<TraceFrame> frames() {
        return Collections.unmodifiableList(frames);
    }

    public List<TraceEvent> events() {
        return Collections.unmodifiableList(events);
    }

    /** Positions of a robot, one per recorded step, metres. */
    public List<Vec2> robotPath(String robot) {
        int i = robotNames.indexOf(robot);
        if (i < 0) {
            throw new IllegalArgumentException("unknown robot '" + robot + "' in trace; known: " + robotNames);
        }
        List<Vec2> out = new ArrayList<>(frames.size());
        for (TraceFrame f : frames) {
            if (i < f.robotX().length) {
                out.add(new Vec2(f.robotX()[i], f.robotY()[i]));
            }
        }
        return out;
    }

    void addRobot(String n) {
        robotNames.add(n);
    }

    void addPerson(String n) {
        personNames.add(n);
    }

    void addItem(String n) {
        itemNames.add(n);
    }

    void add(TraceFrame f) {
        frames.add(f);
    }

    void add(TraceEvent e) {
        events.add(e);
    }
}
