package org.triad.service;

import java.io.IOException;
import java.util.Optional;
import java.util.Properties;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * When a robot is too low on battery to take work, and what it is sent to do then, from the application's
 * {@code META-INF/triad/application.properties}:
 *
 * <pre>
 * charging.below=20                  # percent: a robot reporting less gets no new task
 * charging.task=GoTo                 # optional: the task that sends it to charge, queued for that robot
 * charging.args={"dst": "lobby"}     # the task's arguments, as in POST /api/tasks
 * charging.stopBelow=15              # optional, up to charging.below (the default): percent under which the task a robot
 *                                    # runs is stopped so that it charges first
 * </pre>
 *
 * @param below     percent under which a robot gets no new task
 * @param task      the charging task's submission ({@code {"task", "args"}}), or null for none
 * @param stopBelow percent under which the task a robot runs is stopped (queued again for it) so that it charges first
 */
public record ChargingPolicy(double below, JsonNode task, double stopBelow) {
    public ChargingPolicy(double below, JsonNode task) {
        this(below, task, below);
    }

    public static final String RESOURCE = ApplicationProperties.RESOURCE;

    /** The policy the application's properties on this class loader name, if any; a malformed one is a start-up error. */
    public static Optional<ChargingPolicy> of(ClassLoader loader) {
        return ApplicationProperties.read(loader).flatMap(a -> of(a.values(), a.where()));
    }

    static Optional<ChargingPolicy> of(Properties p, String where) {
        String below = p.getProperty("charging.below");
        if (below == null) {
            if (p.getProperty("charging.task") != null) {
                throw ServiceError.startup(where + ": charging.task needs charging.below=PERCENT (when a robot is sent to charge)");
            }
            return Optional.empty();
        }
        double percent;
        try {
            percent = Double.parseDouble(below.trim());
        } catch (NumberFormatException e) {
            percent = Double.NaN;
        }
        if (!(percent > 0 && percent <= 100)) {
            throw ServiceError.startup(where + ": charging.below takes a percentage above 0 and up to 100, not '" + below + "'");
        }
        double stop = percent;
        String stopBelow = p.getProperty("charging.stopBelow");
        if (stopBelow != null) {
            try {
                stop = Double.parseDouble(stopBelow.trim());
            } catch (NumberFormatException e) {
                stop = Double.NaN;
            }
            if (!(stop > 0 && stop <= percent)) {
                throw ServiceError.startup(where + ": charging.stopBelow takes a percentage above 0 and up to charging.below (" + below.trim()
                        + "), not '" + stopBelow + "'");
            }
        }
        String task = p.getProperty("charging.task");
        if (task == null || task.isBlank()) {
            return Optional.of(new ChargingPolicy(percent, null, stop));
        }
        ObjectMapper json = new ObjectMapper();
        JsonNode args;
        try {
            args = json.readTree(p.getProperty("charging.args", "{}"));
        } catch (IOException e) {
            throw ServiceError.startup(where + ": charging.args is not a JSON object of the task's arguments: " + e.getMessage());
        }
        return Optional.of(new ChargingPolicy(percent, json.createObjectNode().put("task", task.trim()).set("args", args), stop));
    }
}
