package org.triad.examples.hospital;

import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.function.Consumer;

import org.triad.refarc.RefArcRun;
import org.triad.refarc.RefArcRunner;
import org.triad.refarc.Status;
import org.triad.refarc.model.SchemaGoalPlanner;
import org.triad.runtime.app.TaskInstance;
import org.triad.runtime.schema.GoalSolver;
import org.triad.sim.GifReplay;
import org.triad.sim.HtmlReplay;
import org.triad.sim.PersonSpec;
import org.triad.sim.Robot;
import org.triad.sim.Simulation;
import org.triad.sim.TracePicture;
import org.triad.sim.Vec2;

import generated.hospital.HospitalActionExecutor;
import generated.hospital.HospitalSchema;
import generated.hospital.HospitalStateProvider;

/**
 * The simulated hospital, ready to run the generated tasks
 * ({@code new CollectAndDeliver(h.objects().item("gauze"), h.objects().room("storage"), h.objects().room("ward1"))}): the floor of the models on the dyn4j simulation, the
 * courier robot in the lobby, Alice in the lobby and Bob (walking slowly) in ward 2, gauze, syringe and bandage in
 * storage (the models' Morning situation), and the generated StateProvider and ActionExecutor over
 * {@link SimulatedCourier} and {@link SimulatedBuilding}, planned at runtime by Triad's engine through
 * the PDDL translation of the generated schema.
 *
 * <p>Script faults on {@link #sim()} before running: {@code hospital.sim().at(40).closeDoor(HospitalFloor.FIRE_DOOR)}.
 */
public final class HospitalSimulation {
    /** The robot's name in the simulation. */
    public static final String ROBOT = "courier";

    private final HospitalFloor floor = new HospitalFloor();
    private final HospitalObjects objects = new HospitalObjects();
    private final Simulation sim;
    private final PlatformLog log = new PlatformLog();
    private final SimulatedCourier courier;
    private final SimulatedBuilding building;

    /** A hospital simulation with the given random seed (same seed, same run). */
    public HospitalSimulation(long seed) {
        this(seed, true);
    }

    /**
     * @param recordTrace whether to record every frame for the pictures; a long-running service turns
     *                    it off, since the trace grows with every step
     */
    public HospitalSimulation(long seed, boolean recordTrace) {
        sim = Simulation.builder(floor.plan()).seed(seed).recordTrace(recordTrace).build();
        floor.equip(sim);
        Robot robot = sim.addRobot(ROBOT, HospitalFloor.ROBOT_START, HospitalObjects.courierSpec());
        robot.setBattery(HospitalObjects.courierBattery());
        // the models' dock (Building.dock(lobby)), where the courier charges
        sim.addDock(HospitalBuilding.DOCK, floor.plan().waypoint(HospitalBuilding.DOCK).position());
        HospitalFloor.PEOPLE.forEach((name, at) -> sim.addPerson(name, at,
                PersonSpec.defaults().withMaxSpeed(HospitalFloor.WALKING_SPEED.get(name))));
        Whereabouts whereabouts = new Whereabouts(floor);
        courier = new SimulatedCourier(floor, objects, sim, robot, whereabouts, log);
        building = new SimulatedBuilding(floor, objects, sim, courier, whereabouts, log);
    }

    public Simulation sim() {
        return sim;
    }

    public HospitalFloor floor() {
        return floor;
    }

    public HospitalObjects objects() {
        return objects;
    }

    public SimulatedCourier courier() {
        return courier;
    }

    public SimulatedBuilding building() {
        return building;
    }

    /** What the robot and world implementations did, with the simulator's reasons. */
    public PlatformLog platformLog() {
        return log;
    }

    /** Runs the task through RefArc on this simulation; see {@link #run(TaskInstance, Consumer)}. */
    public HospitalRun run(TaskInstance task) {
        return run(task, status -> { });
    }

    /**
     * Runs the task through RefArc on this simulation (synchronously; virtual time advances while
     * actions run), handing each status event to {@code progress} as it happens.
     */
    public HospitalRun run(TaskInstance task, Consumer<? super Status> progress) {
        Objects.requireNonNull(task, "task");
        Objects.requireNonNull(progress, "progress");
        RefArcRunner runner = new RefArcRunner(new HospitalStateProvider(courier, building),
                new SchemaGoalPlanner(new GoalSolver(HospitalSchema.SCHEMA)), new HospitalActionExecutor(courier, building));
        double simStart = sim.time();
        int logStart = log.entries().size();
        long wallStart = System.nanoTime();
        RefArcRun run = runner.run(task, progress);
        double wall = (System.nanoTime() - wallStart) / 1e9;
        List<PlatformLog.Entry> entries = log.entries();
        return new HospitalRun(run, entries.subList(logStart, entries.size()), sim.time() - simStart, wall);
    }

    /**
     * The robot's position, model waypoint and battery, for progress output:
     * {@code (4.00, 14.20) at c1, battery 99.7 %}.
     */
    public String robotWhereabouts() {
        Vec2 p = courier.robot().position();
        return String.format(Locale.ROOT, "(%.2f, %.2f) at %s, battery %.1f %%", p.x(), p.y(), courier.loc(), courier.battery());
    }

    /**
     * Writes {@code <name>.png} (trajectory with numbered action markers), {@code <name>.gif} and
     * {@code <name>.html} (replays) into {@code dir}; returns the files.
     */
    public List<Path> writePictures(Path dir, String name) {
        Path png = dir.resolve(name + ".png");
        Path gif = dir.resolve(name + ".gif");
        Path html = dir.resolve(name + ".html");
        TracePicture.writePng(sim, png);
        GifReplay.write(sim, gif);
        HtmlReplay.write(sim, html);
        return List.of(png, gif, html);
    }
}
