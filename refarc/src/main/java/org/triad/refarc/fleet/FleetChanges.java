package org.triad.refarc.fleet;

/**
 * Where a {@link RobotPlatformProvider} whose robots come and go while the service runs (AGVs announcing
 * themselves on a broker) reports them: {@link FleetContext#changes()}. The service calls nothing back;
 * each method returns at once and may be called from any thread, also before the service is running (it
 * applies them in order once it is).
 */
public interface FleetChanges {
    /** Changes nobody listens to: a context without a running fleet. */
    FleetChanges NONE = new FleetChanges() {
        @Override
        public void joined(FleetRobot robot) {
        }

        @Override
        public void left(String name, String reason) {
        }

        @Override
        public void refused(String name, String reason) {
        }
    };

    /** A robot to dispatch to: a new one, or one that {@link #left} and is back (the same name). */
    void joined(FleetRobot robot);

    /**
     * The robot is gone (e.g. its connection broke) for {@code reason}, the true cause in words: it gets no
     * task until it joins again, and the task it was running ends with this reason.
     */
    void left(String name, String reason);

    /**
     * Something announced itself as a robot that this fleet cannot use (a serial number the configuration
     * does not allow, a factsheet that lacks what the application needs): shown to the operator with the
     * reason, never dispatched to. A later {@link #joined} with the name (e.g. after a corrected factsheet) takes it in.
     */
    void refused(String name, String reason);
}
