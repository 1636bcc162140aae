package org.triad.refarc.fleet;

import org.triad.runtime.app.State;
import org.triad.runtime.schema.AppSchema;

/** What a {@link RobotPlatformProvider} may use to connect robots: the application and its situations. */
public interface FleetContext {
    /** The application's runtime schema, read from its models. */
    AppSchema schema();

    /**
     * A situation of the models: a {@code .state} file name or a situation's name; {@code null} means
     * the one the user chose for the service (or the application's first).
     *
     * @throws IllegalArgumentException when there is no such situation
     */
    State situation(String name);

    /** Where robots that come and go while the fleet runs are reported; {@link FleetChanges#NONE} without a running fleet. */
    default FleetChanges changes() {
        return FleetChanges.NONE;
    }
}
