package org.triad.tests.hospital;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.triad.tests.hospital.HospitalRunAssertions.allActionsSucceeded;
import static org.triad.tests.hospital.HospitalRunAssertions.log;
import static org.triad.tests.hospital.HospitalRunAssertions.milestones;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.triad.examples.hospital.HospitalObjects;
import org.triad.examples.hospital.HospitalRun;
import org.triad.examples.hospital.HospitalSimulation;
import org.triad.examples.hospital.PlatformLog;
import org.triad.examples.hospital.SimulatedBuilding;
import org.triad.refarc.Status;
import org.triad.sim.Room;
import org.triad.sim.Trace;
import org.triad.sim.TraceFrame;
import org.triad.sim.TracePicture;

import generated.hospital.tasks.CollectAndDeliver;
import generated.hospital.tasks.Follow;
import generated.hospital.tasks.Guide;

/**
 * The evaluation's three tasks (Section 6), planned at runtime through RefArc and executed by the
 * handcrafted IRobot/IWorld on the dyn4j simulation of the hospital; what the Status port says is
 * checked against what happened in the simulation.
 */
class HospitalTasksInSimulationTest {
    static final Path PICTURES = Path.of("target", "pictures");

    @Test
    void deliveryBringsTheGauzeFromStorageToWard1() throws Exception {
        HospitalSimulation h = new HospitalSimulation(1);
        HospitalObjects o = h.objects();
        List<Status> live = new ArrayList<>();
        HospitalRun run = h.run(new CollectAndDeliver(o.item("gauze"), o.room("storage"), o.room("ward1")), live::add);

        assertTrue(run.completed(), () -> log(run));
        assertEquals(List.of(
                "task CollectAndDeliver(gauze, storage, ward1) started",
                "plan for IsAt(storage): Courier.move(lobby, c4), Courier.move(c4, c1), Courier.move(c1, storage)",
                "goal IsAt(storage) satisfied",
                "plan for Holds(gauze): Courier.pick(gauze, storage)",
                "goal Holds(gauze) satisfied",
                "plan for Delivered(gauze, ward1): Courier.move(storage, c1), Courier.move(c1, c2), Courier.move(c2, c3),"
                        + " Courier.move(c3, ward1), Courier.drop(gauze, ward1)",
                "goal Delivered(gauze, ward1) satisfied",
                "task CollectAndDeliver(gauze, storage, ward1) completed"), milestones(run));
        allActionsSucceeded(run);
        assertEquals(run.refArc().statuses(), live, "the observer saw every status as it happened");

        // in the simulation: the gauze lies in ward 1, nobody holds it, the other supplies stayed in storage
        org.triad.sim.Item gauze = h.sim().item("gauze");
        assertEquals("ward1", gauze.room().map(Room::name).orElse("none"));
        assertTrue(gauze.holder().isEmpty());
        assertEquals(List.of("syringe", "bandage"), h.sim().itemsIn("storage").stream().map(org.triad.sim.Item::name).toList());
        assertEquals("ward1", h.courier().robot().room().map(Room::name).orElse("none"));
        assertTrue(run.simSeconds() > 40 && run.simSeconds() < 120, "about 50 m at up to 1 m/s: " + run.simSeconds());

        List<Path> pictures = h.writePictures(PICTURES, "delivery");
        for (Path p : pictures) {
            assertTrue(Files.size(p) > 1000, p + " is written");
        }
    }

    @Test
    void guidingLeadsAliceFromTheLobbyToXray() {
        HospitalSimulation h = new HospitalSimulation(2);
        HospitalObjects o = h.objects();
        assertEquals("lobby", h.sim().person("alice").room().map(Room::name).orElse("none"));
        HospitalRun run = h.run(new Guide(o.person("alice"), o.room("xray")));

        assertTrue(run.completed(), () -> log(run));
        assertEquals(List.of(
                "task Guide(alice, xray) started",
                "plan for PersonAt(alice, xray): Courier.guide(alice, lobby, c4), Courier.guide(alice, c4, c1),"
                        + " Courier.guide(alice, c1, c2), Courier.guide(alice, c2, xray)",
                "goal PersonAt(alice, xray) satisfied",
                "task Guide(alice, xray) completed"), milestones(run));
        allActionsSucceeded(run);
        assertEquals("xray", h.sim().person("alice").room().map(Room::name).orElse("none"));
        assertEquals("xray", h.courier().robot().room().map(Room::name).orElse("none"));
        // guided, not carried off: Alice stayed close behind the robot all the way
        Trace trace = h.sim().trace();
        int alice = trace.personNames().indexOf("alice");
        double farthest = 0;
        for (TraceFrame f : trace.frames()) {
            farthest = Math.max(farthest, Math.hypot(f.robotX()[0] - f.personX()[alice], f.robotY()[0] - f.personY()[alice]));
        }
        assertTrue(farthest < 4, "Alice was at most " + farthest + " m from the robot");
        TracePicture.writePng(h.sim(), PICTURES.resolve("guide.png"));
    }

    @Test
    void followingKeepsBobWithinTheDistanceBandAllTheWayToTheLobby() {
        HospitalSimulation h = new HospitalSimulation(3);
        HospitalObjects o = h.objects();
        HospitalRun run = h.run(new Follow(o.person("bob"), o.room("lobby")));

        assertTrue(run.completed(), () -> log(run));
        // Bob walks his own way (Building.walksAhead), so the courier follows him and does not lead him: guiding him
        // to the lobby and following him there would be as short, but it is not the courier's to choose for him
        assertEquals(List.of(
                "task Follow(bob, lobby) started",
                "plan for FollowedTo(bob, lobby): Courier.move(lobby, c4), Courier.move(c4, c5), Courier.move(c5, c6),"
                        + " Courier.move(c6, ward2), Courier.startFollowing(bob, ward2), Building.walk(bob, ward2, c6),"
                        + " Building.walk(bob, c6, c5), Building.walk(bob, c5, c4), Building.walk(bob, c4, lobby)",
                "goal FollowedTo(bob, lobby) satisfied",
                "task Follow(bob, lobby) completed"), milestones(run));
        allActionsSucceeded(run);
        assertEquals("lobby", h.sim().person("bob").room().map(Room::name).orElse("none"));

        // while Bob walked (from the first follow to the end of the last), the robot kept its distance band
        List<PlatformLog.Entry> follows = run.platform().stream().filter(e -> e.call().startsWith("follow(bob")).toList();
        assertEquals(4, follows.size(), () -> log(run));
        double from = follows.get(0).start();
        double to = follows.get(follows.size() - 1).time();
        Trace trace = h.sim().trace();
        int bob = trace.personNames().indexOf("bob");
        double nearest = Double.POSITIVE_INFINITY;
        double farthest = 0;
        int frames = 0;
        for (TraceFrame f : trace.frames()) {
            if (f.time() >= from && f.time() <= to) {
                double d = Math.hypot(f.robotX()[0] - f.personX()[bob], f.robotY()[0] - f.personY()[bob]);
                nearest = Math.min(nearest, d);
                farthest = Math.max(farthest, d);
                frames++;
            }
        }
        assertTrue(frames > 600, "Bob walked for " + frames + " frames");
        assertTrue(nearest >= SimulatedBuilding.FOLLOW_MIN, "the robot came as close as " + nearest + " m");
        assertTrue(farthest <= SimulatedBuilding.FOLLOW_MAX + 0.1, "the robot fell back to " + farthest + " m");
        TracePicture.writePng(h.sim(), PICTURES.resolve("follow.png"));
    }
}
