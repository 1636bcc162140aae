package org.triad.runtime.component;

/**
 * A handler or an activity of a component threw. The runtime delivers faults to the {@code faults}
 * port of the nearest enclosing composed component that connects it, else to the scheduler's fault
 * listener.
 *
 * @param componentPath the path of the faulty component, e.g. {@code refArc.planner}
 * @param port          the in port whose message was being handled, or {@code activity NAME}
 * @param message       the message being handled; for an activity, its subject (may be null)
 * @param cause         what was thrown
 */
public record ComponentFault(String componentPath, String port, Object message, Throwable cause) {
    public ComponentFault {
        if (componentPath == null || port == null || cause == null) {
            throw new IllegalArgumentException("a fault needs a component path, a port and a cause");
        }
    }

    /** The cause's class and message, e.g. {@code IllegalStateException: no route}. */
    public String causeDescription() {
        String m = cause.getMessage();
        return cause.getClass().getSimpleName() + (m == null ? "" : ": " + m);
    }

    @Override
    public String toString() {
        return "fault in " + componentPath + " at " + port + " handling " + message + ": " + causeDescription();
    }
}
