package org.triad.examples.hospital;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.triad.runtime.app.GroundAction;
import org.triad.refarc.Status;
import org.triad.runtime.app.TaskInstance;

import generated.hospital.tasks.CollectAndDeliver;
import generated.hospital.tasks.Guide;

/**
 * Benchmark main (not a test): what the simulated courier drains against what the models' metres say, per kind of
 * step and per trip. Runs the hospital's trips through RefArc on the dyn4j simulation (Morning, the courier in the lobby
 * at 100 %), reads the battery when each driving action starts and ends, and prints a Markdown table: the models'
 * metres ({@code Building.distance}, what the plan drains as {@code drain() * metres}), the metres the battery's drop
 * stands for (drop / drain), and how much more that is. Usage: {@code HospitalDrainBenchmark [SEED]}.
 */
public final class HospitalDrainBenchmark {
    /** One driving step: its kind, the models' metres and the metres the simulated battery paid for. */
    record Step(String kind, String action, double modelMetres, double drivenMetres) {
    }

    /** The trips measured: the evaluation's delivery, the delivery upstairs by the lift, a guide. */
    static Map<String, java.util.function.Function<HospitalObjects, TaskInstance>> trips() {
        Map<String, java.util.function.Function<HospitalObjects, TaskInstance>> trips = new LinkedHashMap<>();
        trips.put("gauze: lobby - storage - ward 1 (floor 0)", o -> new CollectAndDeliver(o.item("gauze"), o.room("storage"), o.room("ward1")));
        trips.put("insulin: lobby - pharmacy - ward 4 (door, lift)", o -> new CollectAndDeliver(o.item("insulin"), o.room("pharmacy"), o.room("ward4")));
        trips.put("Alice: lobby - x-ray (guide)", o -> new Guide(o.person("alice"), o.room("xray")));
        return trips;
    }

    /** The driving steps of one trip from the lobby at 100 %, with what each drained. */
    static List<Step> drive(long seed, java.util.function.Function<HospitalObjects, TaskInstance> trip) {
        HospitalSimulation h = new HospitalSimulation(seed, false);
        SimulatedCourier courier = h.courier();
        List<Step> steps = new ArrayList<>();
        double[] before = new double[1];
        HospitalRun run = h.run(trip.apply(h.objects()), status -> {
            if (status instanceof Status.ActionStarted s) {
                before[0] = courier.battery();
            } else if (status instanceof Status.ActionSucceeded s && kind(s.action()) != null) {
                List<?> args = s.action().args();
                double metres = SimulatedBuilding.routeLength(h.floor(), args.get(args.size() - 2).toString(), args.get(args.size() - 1).toString());
                steps.add(new Step(kind(s.action()), s.action().action() + args.toString().replace('[', '(').replace(']', ')'), metres,
                        (before[0] - courier.battery()) / courier.drain()));
            }
        });
        if (!run.completed()) {
            throw new IllegalStateException("the trip did not complete: " + run);
        }
        return steps;
    }

    /** The kind of a driving step, or null for one that does not drive (pick, drop, recharge, startFollowing). */
    static String kind(GroundAction a) {
        return switch (a.action()) {
            case "move" -> "move";
            case "passDoor" -> "passDoor (pharmacy door)";
            case "ride" -> "ride (lift)";
            case "guide" -> "guide";
            case "walk" -> "walk (following)";
            default -> null;
        };
    }

    public static void main(String[] args) {
        long seed = args.length > 0 ? Long.parseLong(args[0]) : 1;
        Map<String, double[]> byKind = new LinkedHashMap<>();
        System.out.println("| trip or kind of step | steps | models' metres | metres the battery paid for | more than the models |");
        System.out.println("|---|---|---|---|---|");
        for (Map.Entry<String, java.util.function.Function<HospitalObjects, TaskInstance>> trip : trips().entrySet()) {
            List<Step> steps = drive(seed, trip.getValue());
            double model = steps.stream().mapToDouble(Step::modelMetres).sum();
            double driven = steps.stream().mapToDouble(Step::drivenMetres).sum();
            row(trip.getKey(), steps.size(), model, driven);
            for (Step s : steps) {
                double[] k = byKind.computeIfAbsent(s.kind(), x -> new double[3]);
                k[0]++;
                k[1] += s.modelMetres();
                k[2] += s.drivenMetres();
                System.err.printf(Locale.ROOT, "  %s: %.2f m in the models, %.2f m paid%n", s.action(), s.modelMetres(), s.drivenMetres());
            }
        }
        byKind.forEach((kind, k) -> row(kind, (int) k[0], k[1], k[2]));
    }

    private static void row(String label, int steps, double model, double driven) {
        System.out.printf(Locale.ROOT, "| %s | %d | %.1f | %.1f | %+.1f %% |%n", label, steps, model, driven, 100 * (driven / model - 1));
    }
}
