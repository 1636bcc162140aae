package org.triad.refarc.fleet;

import java.util.List;

/**
 * How an application project (or a robot binding such as VDA 5050) hands its robots to a fleet
 * service, found with {@link java.util.ServiceLoader}: list the implementing class in
 * {@code META-INF/services/org.triad.refarc.fleet.RobotPlatformProvider}. The service picks the
 * provider whose {@link #scheme()} matches the {@code SCHEME:ARGUMENT} the user gave (e.g.
 * {@code sim:3}) and whose {@link #application()} matches the loaded models.
 */
public interface RobotPlatformProvider {
    /** Application-independent providers (robots that work for any models) answer this. */
    String ANY_APPLICATION = "*";

    /** The application these robots belong to: the class diagram's name (e.g. {@code Hospital}), or {@link #ANY_APPLICATION}. */
    String application();

    /** The scheme users write before the colon, e.g. {@code sim}, {@code dry}, {@code vda5050}. */
    String scheme();

    /** One line for {@code --help} and error messages, e.g. {@code sim:N  N simulated hospital robots}. */
    String usage();

    /**
     * Connects the robots {@code argument} (the text after the colon) names.
     *
     * @throws IllegalArgumentException for an argument this provider does not understand; its message is shown to the user as is
     * @throws Exception when the robots cannot be reached
     */
    List<FleetRobot> connect(String argument, FleetContext context) throws Exception;
}
