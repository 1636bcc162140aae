package org.triad.tests.service;

import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;

import org.triad.building.traffic.TrafficBoard;
import org.triad.service.Views.EventView;
import org.triad.service.Views.RobotView;
import org.triad.service.Views.TaskView;

/**
 * Where the building benchmark's time goes, two ways: the robots' time, sampled while it runs (idle, out of dispatch,
 * charging, waiting in the traffic table, running an action of which kind), and the tasks' time, from each task's
 * timeline in the service's database (waiting for dispatch, planning, actions that succeeded and that failed by kind,
 * with the failures' causes). Wall seconds; the benchmark multiplies by its speed for simulated ones.
 */
final class TaskTimeSplit {
    private static final Pattern STARTED = Pattern.compile("^action \\d+/\\d+ ([\\w.]+)\\(");
    private final Map<String, Double> robotSeconds = new TreeMap<>();
    private long lastSample;

    /** One look at every robot: the wall time since the last look is booked on what each robot does now. */
    void sample(List<RobotView> robots, List<TrafficBoard.Waiting> waits) {
        long now = System.nanoTime();
        double dt = lastSample == 0 ? 0 : (now - lastSample) / 1e9;
        lastSample = now;
        Set<String> waiting = waits.stream().map(w -> w.robot().substring(w.robot().lastIndexOf('/') + 1)).collect(Collectors.toSet());
        for (RobotView r : robots) {
            String what;
            if (r.task() == null) {
                what = r.online() ? "idle (no task; resting or parking included)" : "out of dispatch";
            } else if (r.call() != null && r.call().startsWith("Recharge")) {
                what = "charging task (driving to the dock and charging)";
            } else if (waiting.contains(r.name())) {
                what = "task: waiting in the traffic table";
            } else if (r.step() >= 1 && r.step() <= r.plan().size()) {
                String a = r.plan().get(r.step() - 1);
                what = "task: action " + (a.contains("(") ? a.substring(0, a.indexOf('(')) : a) + " (not waiting)";
            } else {
                what = "task: planning (no action yet)";
            }
            robotSeconds.merge(what, dt, Double::sum);
        }
    }

    /** The split of the robots' time, and of the tasks' time from their timelines, in simulated seconds. */
    void print(List<TaskView> tasks, double speed) {
        double total = robotSeconds.values().stream().mapToDouble(Double::doubleValue).sum();
        System.out.printf(Locale.ROOT, "%nrobots' time (sampled every 0.2 s wall; %.0f robot-simulated-s):%n", total * speed);
        robotSeconds.forEach((k, v) -> System.out.printf(Locale.ROOT, "  %5.1f %%  %8.0f s  %s%n", 100 * v / total, v * speed, k));
        Map<String, Double> split = new TreeMap<>();
        Map<String, Integer> failures = new TreeMap<>();
        Map<String, Integer> counts = new TreeMap<>();
        for (TaskView t : tasks) {
            List<EventView> ev = t.events();
            String action = "?";
            boolean onRobot = false;
            for (int i = 0; i + 1 < ev.size(); i++) {
                EventView a = ev.get(i);
                EventView b = ev.get(i + 1);
                if (a.kind().equals("action_started")) {
                    Matcher m = STARTED.matcher(a.text());
                    action = m.find() ? m.group(1) : "?";
                }
                if (a.kind().equals("dispatched")) {
                    onRobot = true;
                } else if (Set.of("task_completed", "task_aborted", "congestion_requeued", "interrupted", "refused").contains(a.kind())) {
                    onRobot = false;
                }
                double s = Duration.between(Instant.parse(a.at()), Instant.parse(b.at())).toNanos() / 1e9;
                String what = !onRobot ? "waiting for dispatch (queued, waiting for an object, paused after congestion or a stop)" : switch (b.kind()) {
                    case "plan_found" -> "planning (after start, a goal, or a failure)";
                    case "action_succeeded" -> "action " + action + ", succeeded";
                    case "action_failed" -> "action " + action + ", failed";
                    default -> a.kind().equals("action_started") ? "action " + action + ", ended by the task's end" : "between steps (" + a.kind() + " -> " + b.kind() + ")";
                };
                split.merge((t.task().equals("Recharge") ? "[Recharge] " : "") + what, s, Double::sum);
                counts.merge(b.kind(), 1, Integer::sum);
                if (b.kind().equals("action_failed")) {
                    failures.merge(action + ": " + cause(b.text()), 1, Integer::sum);
                }
            }
        }
        double sum = split.values().stream().mapToDouble(Double::doubleValue).sum();
        System.out.printf(Locale.ROOT, "tasks' time from their timelines (%d tasks, %.0f task-simulated-s):%n", tasks.size(), sum * speed);
        split.forEach((k, v) -> System.out.printf(Locale.ROOT, "  %5.1f %%  %8.0f s  %s%n", 100 * v / sum, v * speed, k));
        System.out.printf(Locale.ROOT, "events: %s%n", counts);
        System.out.println("failed actions by cause:");
        failures.entrySet().stream().sorted(Map.Entry.<String, Integer>comparingByValue().reversed())
                .forEach(e -> System.out.printf(Locale.ROOT, "  %4d x %s%n", e.getValue(), e.getKey()));
    }

    private static String cause(String text) {
        String t = text.toLowerCase(Locale.ROOT);
        if (t.contains("deadlock avoided")) {
            return "refused by traffic control, deadlock avoided";
        }
        if (t.contains("the wait bound")) {
            return "waited over the bound";
        }
        if (t.contains("stands at") && t.contains("traffic map")) {
            return "traffic map and AGV disagree on where it stands";
        }
        for (String code : List.of("PATH_BLOCKED", "PERSON_LOST", "TIMEOUT", "DOOR_CLOSED", "REFUSED", "made way", "battery")) {
            if (text.contains(code)) {
                return code;
            }
        }
        String s = text.replaceAll("\\d+(\\.\\d+)?", "N");
        return s.length() > 140 ? s.substring(0, 140) : s;
    }
}
