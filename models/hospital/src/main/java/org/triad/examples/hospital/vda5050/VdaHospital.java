package org.triad.examples.hospital.vda5050;

import java.util.Objects;
import java.util.function.Consumer;

import org.triad.examples.hospital.HospitalFloor;
import org.triad.examples.hospital.HospitalObjects;
import org.triad.refarc.RefArcRun;
import org.triad.refarc.RefArcRunner;
import org.triad.refarc.Status;
import org.triad.refarc.model.SchemaGoalPlanner;
import org.triad.runtime.app.TaskInstance;
import org.triad.runtime.schema.GoalSolver;
import org.triad.vda5050.master.MasterControl;
import org.triad.vda5050.master.RemoteAgv;
import org.triad.vda5050.master.TrafficControl;

import generated.hospital.HospitalActionExecutor;
import generated.hospital.HospitalSchema;
import generated.hospital.HospitalStateProvider;

/**
 * The hospital application on a VDA 5050 AGV instead of the in-process simulation: the generated
 * StateProvider and ActionExecutor over {@link VdaCourier} and {@link VdaBuilding}, one RefArc per robot.
 * Several robots in one process share one {@link MasterControl} (one broker connection, own topics each):
 *
 * <pre>{@code
 * try (MasterControl master = MasterControl.connect("tcp://127.0.0.1:1883", VdaTimeouts.defaults(), System.err::println)) {
 *     VdaHospital h = new VdaHospital(master, "courier-1");
 *     RefArcRun run = h.run(new GoTo(h.objects().room("ward3")), System.out::println);
 * }
 * }</pre>
 */
public final class VdaHospital implements AutoCloseable {
    /**
     * What master control knows of items and people, one per master: its couriers share one building, so a person
     * that one courier guided, or an item it picked, is where that courier left them for every other courier too.
     */
    private static final java.util.Map<MasterControl, HospitalKnowledge> KNOWLEDGE = java.util.Collections.synchronizedMap(new java.util.WeakHashMap<>());
    private final HospitalObjects objects = new HospitalObjects();
    private final VdaCourier courier;
    private final VdaBuilding building;
    private final BuildingDevices devices;

    /** Doors and lifts are reached over the master's connection with the default timeouts (10 s a door, 60 s a lift). */
    public VdaHospital(MasterControl master, String serialNumber) {
        this(master, serialNumber, null);
    }

    /**
     * The robot with its drives under {@code traffic} (each move and guide reserves its lane, doors and corridor
     * first, see {@link RemoteAgv#driveRoute}); null drives each edge at once. Doors and lifts with the default timeouts.
     */
    public VdaHospital(MasterControl master, String serialNumber, TrafficControl traffic) {
        this(master, serialNumber, traffic, BuildingDevices.DOOR_SECONDS, BuildingDevices.LIFT_SECONDS);
    }

    /**
     * @param doorSeconds wall-clock seconds to wait for the building to open or close a door (&gt; 0)
     * @param liftSeconds wall-clock seconds to wait for the lift to stand open at a floor (&gt; 0)
     */
    public VdaHospital(MasterControl master, String serialNumber, double doorSeconds, double liftSeconds) {
        this(master, serialNumber, null, doorSeconds, liftSeconds);
    }

    /**
     * @param traffic the fleet's traffic control, or null to drive each edge at once
     * @param doorSeconds wall-clock seconds to wait for the building to open or close a door (&gt; 0)
     * @param liftSeconds wall-clock seconds to wait for the lift to stand open at a floor (&gt; 0)
     */
    public VdaHospital(MasterControl master, String serialNumber, TrafficControl traffic, double doorSeconds,
            double liftSeconds) {
        Objects.requireNonNull(master, "master");
        RemoteAgv agv = master.agv(serialNumber);
        HospitalKnowledge knowledge = KNOWLEDGE.computeIfAbsent(master, m -> new HospitalKnowledge());
        devices = new BuildingDevices(master, serialNumber, doorSeconds, liftSeconds, System.err::println);
        courier = new VdaCourier(agv, objects, knowledge, traffic);
        HospitalFloor floor = new HospitalFloor();
        // under traffic control the doors it keeps open on reservation: a door closed because nobody needed it blocks no plan
        building = new VdaBuilding(agv, floor, objects, knowledge, devices, traffic,
                traffic == null ? java.util.List.of() : HospitalTraffic.keptDoors(floor));
    }

    public HospitalObjects objects() {
        return objects;
    }

    public VdaCourier courier() {
        return courier;
    }

    public VdaBuilding building() {
        return building;
    }

    /** Drops the subscriptions to the building's devices that door or lift actions made (master control's connection stays). */
    @Override
    public void close() {
        devices.close();
    }

    /** Runs the task through a fresh RefArc on this robot (synchronously), handing each status event to {@code progress}. */
    public RefArcRun run(TaskInstance task, Consumer<? super Status> progress) {
        RefArcRunner runner = new RefArcRunner(new HospitalStateProvider(courier, building),
                new SchemaGoalPlanner(new GoalSolver(HospitalSchema.SCHEMA)), new HospitalActionExecutor(courier, building));
        return runner.run(task, progress);
    }
}
