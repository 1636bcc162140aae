package org.triad.building;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.Set;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.generator.SchemaBuilder;
import org.triad.generator.SituationReader;
import org.triad.refarc.ActionRunner;
import org.triad.refarc.StateSource;
import org.triad.refarc.fleet.FleetRobot;
import org.triad.refarc.model.DryRunWorld;
import org.triad.runtime.app.Atom;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.AppSchema;
import org.triad.runtime.schema.GoalSolver;

/** One building, many robots, on the hospital's models: one world, one robot actor instance per robot, claims on objects. */
class SharedWorldTest {
    private static AppSchema schema;
    private static State morning;

    @BeforeAll
    static void load() {
        LoadedApplication app = ApplicationAssembler.load(Path.of("../models/hospital/src/main/models").toAbsolutePath().normalize());
        assertFalse(app.hasErrors(), app.diagnostics().toString());
        schema = SchemaBuilder.build(app.application());
        morning = SituationReader.read(app.application().getSituations().stream().filter(s -> s.getName().equals("Morning")).findFirst()
                .orElseThrow(), schema);
    }

    private static Object o(String name) {
        return morning.object(name).orElseThrow();
    }

    private static GroundAction move(String a, String b) {
        return new GroundAction("Courier", "move", List.of(o(a), o(b)));
    }

    private static void toStorage(ModelRobot r) {
        for (GroundAction a : List.of(move("lobby", "c4"), move("c4", "c1"), move("c1", "storage"))) {
            assertTrue(r.execute(a), a + " on " + r.name());
        }
    }

    private static Atom carries(String item) {
        return Atom.of("Courier", "carries", o(item));
    }

    private static Atom itemAt(String item, String where) {
        return Atom.of("Building", "itemAt", o(item), o(where));
    }

    @Test
    void anItemOneRobotPickedUpIsGoneForEveryOtherRobot() {
        SharedWorld world = new SharedWorld(schema, morning);
        ModelRobot r1 = world.modelRobot("r1");
        ModelRobot r2 = world.modelRobot("r2");
        toStorage(r1);
        assertTrue(r1.execute(new GroundAction("Courier", "pick", List.of(o("gauze"), o("storage")))));
        assertTrue(r1.currentState().holds(carries("gauze")), "the robot executing holds it");
        assertFalse(r2.currentState().holds(carries("gauze")), "Courier.carries(gauze) means the executing robot, not the fleet");
        assertFalse(r2.currentState().holds(itemAt("gauze", "storage")), "gone from storage for the other robot");
        assertEquals(o("lobby"), r2.currentState().valueOf(Atom.of("Courier", "loc")).orElseThrow(), "each robot has its own place");
        GoalSolver solver = new GoalSolver(schema);
        assertFalse(solver.plan("Holds", List.of(o("gauze")), r2.currentState()).planned(), "the other robot cannot get the gauze");
        assertTrue(solver.plan("Holds", List.of(o("syringe")), r2.currentState()).planned(), "but the syringe is still there");
    }

    @Test
    void ofTwoRobotsReachingForOneItemOneGetsItTheOtherFailsWithTheReason() {
        SharedWorld world = new SharedWorld(schema, morning);
        ModelRobot r1 = world.modelRobot("r1");
        ModelRobot r2 = world.modelRobot("r2");
        toStorage(r1);
        toStorage(r2);
        GroundAction pick = new GroundAction("Courier", "pick", List.of(o("gauze"), o("storage")));
        State planned = r2.currentState();
        assertEquals(Optional.empty(), r2.violatedPrecondition(pick, planned), "both planned it");
        assertTrue(r1.execute(pick));
        assertFalse(r2.execute(pick));
        assertTrue(r2.failureReason(pick).orElseThrow().contains("another robot acted"), r2.failureReason(pick).orElseThrow());
        assertFalse(r2.currentState().holds(carries("gauze")));
    }

    @Test
    void aRobotOfTheBuildingParksOutOfTheWayAsItsPlatformDoes() {
        SharedWorld world = new SharedWorld(schema, morning);
        DryRunWorld platform = new DryRunWorld(schema, morning);
        FleetRobot own = new PlatformRobot(platform, java.util.Optional.of("parked out of the way: c4 -> lobby -> lobby.3"));
        // the wrapper used to answer with FleetRobot's default (stays): the benchmark's couriers never parked
        assertEquals(java.util.Optional.of("parked out of the way: c4 -> lobby -> lobby.3"), world.observing(own).parkOutOfTheWay());
    }

    @Test
    void whatAPlatformReportsChangedWhileItsRobotActedIsWrittenIntoTheBuilding() throws Exception {
        SharedWorld world = new SharedWorld(schema, morning);
        DryRunWorld platform = new DryRunWorld(schema, morning); // a platform with a world view of its own
        FleetRobot own = new PlatformRobot(platform, java.util.Optional.empty());
        FleetRobot member = world.observing(own);
        assertTrue(member == world.observing(member), "a member is not wrapped twice");
        ModelRobot other = world.modelRobot("r2");
        for (GroundAction a : List.of(move("lobby", "c4"), move("c4", "c1"), move("c1", "storage"),
                new GroundAction("Courier", "pick", List.of(o("bandage"), o("storage"))))) {
            assertTrue(member.actionRunner().execute(a));
        }
        assertFalse(world.worldState().holds(itemAt("bandage", "storage")), "the pick the platform reported");
        assertFalse(other.currentState().holds(itemAt("bandage", "storage")));
        assertTrue(member.stateSource().currentState().holds(carries("bandage")));
        assertTrue(world.worldState().holds(itemAt("gauze", "storage")));
    }

    /**
     * Two couriers in one simulation (a platform that observes the whole building): what changed there is in the
     * building at the next report, though neither of them acted; what a robot without a body there changed stays.
     */
    @Test
    void aPlatformObservingTheWholeBuildingIsFollowedAtEveryReport() throws Exception {
        SharedWorld world = new SharedWorld(schema, morning);
        DryRunWorld simulation = new DryRunWorld(schema, morning);
        FleetRobot p1 = world.observing(inSimulation("p1", simulation));
        FleetRobot p2 = world.observing(inSimulation("p2", simulation));
        ModelRobot bodiless = world.modelRobot("r3");
        toStorage(bodiless);
        assertTrue(bodiless.execute(new GroundAction("Courier", "pick", List.of(o("syringe"), o("storage")))));
        // someone else in the simulation takes the bandage; neither p1 nor p2 acted
        for (GroundAction a : List.of(move("lobby", "c4"), move("c4", "c1"), move("c1", "storage"),
                new GroundAction("Courier", "pick", List.of(o("bandage"), o("storage"))))) {
            assertTrue(simulation.execute(a));
        }
        assertTrue(world.worldState().holds(itemAt("bandage", "storage")), "not read yet");
        assertFalse(p2.stateSource().currentState().holds(itemAt("bandage", "storage")), "the next report has it");
        assertFalse(world.worldState().holds(itemAt("bandage", "storage")));
        assertFalse(world.worldState().holds(itemAt("syringe", "storage")), "the bodiless robot's pick stays");
        assertFalse(p1.stateSource().currentState().holds(itemAt("syringe", "storage")));
        assertTrue(world.worldState().holds(itemAt("gauze", "storage")));
    }

    private static FleetRobot inSimulation(String name, DryRunWorld simulation) {
        return new FleetRobot() {
            @Override
            public String name() {
                return name;
            }

            @Override
            public StateSource stateSource() {
                return simulation;
            }

            @Override
            public ActionRunner actionRunner() {
                return simulation;
            }

            @Override
            public boolean observesBuilding() {
                return true;
            }
        };
    }

    @Test
    void aTaskClaimsTheObjectsItNamesThatAreNotPlaces() {
        Claims claims = new Claims(schema);
        assertEquals(Set.of("WayPoint", "Room"), claims.places());
        assertEquals(Set.of("gauze"), claims.claimedBy("CollectAndDeliver", List.of(o("gauze"), o("storage"), o("ward1"))));
        assertEquals(Set.of("alice"), claims.claimedBy("Guide", List.of(o("alice"), o("ward1"))));
        assertEquals(Set.of(), claims.claimedBy("GoTo", List.of(o("ward1"))));
        claims.take(1, "r1", Set.of("gauze"));
        assertEquals("gauze, held by task 1 on r1", claims.holder(2, Set.of("gauze")).orElseThrow().describe());
        assertEquals(Optional.empty(), claims.holder(1, Set.of("gauze")), "a task does not wait for itself");
        assertEquals(Optional.empty(), claims.holder(2, Set.of("syringe")));
        assertThrows(IllegalStateException.class, () -> claims.take(2, "r2", Set.of("gauze")));
        claims.release(1);
        assertEquals(Optional.empty(), claims.holder(2, Set.of("gauze")));
    }

    /** Robot "p1" on a platform with a world view of its own, parking out of the way as {@code parked} says. */
    private record PlatformRobot(DryRunWorld platform, java.util.Optional<String> parked) implements FleetRobot {
        @Override
        public String name() {
            return "p1";
        }

        @Override
        public StateSource stateSource() {
            return platform;
        }

        @Override
        public ActionRunner actionRunner() {
            return platform;
        }

        @Override
        public java.util.Optional<String> parkOutOfTheWay() {
            return parked;
        }
    }
}
