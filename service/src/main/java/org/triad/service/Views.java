package org.triad.service;

import java.time.Instant;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;

/** What the API returns, as JSON (Jackson serialises these records field by field). */
public final class Views {
    private Views() {
    }

    public record TaskView(long id, String task, JsonNode args, String call, String state, String robot, String preferredRobot,
            String reason, String submittedAt, String updatedAt, List<EventView> events, int priority, String expectedStart, String expectedFinish) {
    }

    public record EventView(long id, String at, String kind, String robot, String text) {
    }

    /**
     * {@code offlineReason}: why the robot is out of dispatch (the operator, tasks aborted on it in a row, its
     * platform reporting it gone, or refused when it announced itself), or null; {@code presence}: online,
     * offline (out of dispatch), gone or refused; {@code pose} and {@code battery} as its platform reports them, or null;
     * {@code batteryNote}: why it gets no new task for its battery (the charging policy), or null.
     */
    public record RobotView(String name, boolean online, Long task, String call, List<String> plan, int step, boolean map, String offlineReason,
            String presence, org.triad.refarc.fleet.Pose pose, org.triad.refarc.fleet.Battery battery, String batteryNote) {
    }

    /**
     * The building's map: every robot (with its {@code pose}, whose {@code mapId} says the floor), and the
     * layout (rooms, walls, doors, waypoints, items, people) the first robot with a floor map draws, on
     * {@code layoutMap} (that robot's map id), or null when no platform draws one; {@code floors}: every floor's
     * layout by map id, for a building of several floors (one map each), else just {@code layoutMap}'s.
     */
    public record BuildingView(List<RobotView> robots, org.triad.refarc.fleet.FloorMap layout, String layoutMap,
            java.util.Map<String, org.triad.refarc.fleet.FloorMap> floors) {
    }

    public record RequestView(long id, long task, String call, String robot, String goal, String reason, String raisedAt, String resolvedAt,
            String resolution) {
    }

    /**
     * The database (address without password), whether it works, its outages (now and healed) and,
     * with several instances on one server, whether this one dispatches and the lease's history.
     */
    public record HealthView(String database, boolean ok, List<String> outages, boolean shared, boolean dispatching, List<String> lease) {
    }

    /** One message of the live stream: {@code type} task, robot or request, and its view. */
    public record LiveEvent(String type, Object data) {
    }

    static String time(Instant t) {
        return t == null ? null : t.toString();
    }
}
