package org.triad.sim;

import org.dyn4j.dynamics.Body;

/**
 * A door of the running simulation. A closed door is a static body filling its doorway; closing is
 * deferred while someone stands in the doorway. Change it through {@link Simulation#openDoor},
 * {@link Simulation#closeDoor}, scripted events or the robot's {@link Robot#openDoor}.
 */
public final class Door {
    private final Doorway doorway;
    final Body body;
    private boolean open;
    private boolean locked;
    private boolean closeRequested;

    Door(Doorway doorway, Body body) {
        this.doorway = doorway;
        this.body = body;
        this.open = doorway.initiallyOpen();
        body.setEnabled(!open);
    }

    public String name() {
        return doorway.name();
    }

    public Doorway doorway() {
        return doorway;
    }

    public boolean isOpen() {
        return open;
    }

    public boolean isLocked() {
        return locked;
    }

    /** Whether a close was requested and waits for the doorway to be clear. */
    public boolean isClosing() {
        return closeRequested;
    }

    void open() {
        closeRequested = false;
        open = true;
        body.setEnabled(false);
    }

    void requestClose() {
        if (open) {
            closeRequested = true;
        }
    }

    void setLocked(boolean locked) {
        this.locked = locked;
    }

    /** Closes a pending door once no agent overlaps the doorway; returns whether it closed now. */
    boolean update(Iterable<? extends Agent> agents, double wallThickness) {
        if (!closeRequested) {
            return false;
        }
        for (Agent a : agents) {
            if (a.body != null && Segments.pointDistance(a.position(), doorway.end1(), doorway.end2())
                    < a.radius + wallThickness / 2 + 0.02) {
                return false;
            }
        }
        closeRequested = false;
        open = false;
        body.setEnabled(true);
        return true;
    }
}
