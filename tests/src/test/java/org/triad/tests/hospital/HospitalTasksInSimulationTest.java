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
    void bobIsBroughtToTheLobbyAndFollowedThere() {
        HospitalSimulation h = new HospitalSimulation(3);
        HospitalObjects o = h.objects();
        HospitalRun run = h.run(new Follow(o.person("bob"), o.room("lobby")));

        assertTrue(run.completed(), () -> log(run));
        // Of the two cheapest plans of fewest steps (start following Bob at ward 2 and let him walk, or guide him
        // and start following in the lobby: the same metres, 9 steps each), the cost search takes the second.
        assertEquals(List.of(
                "task Follow(bob, lobby) started",
                "plan for FollowedTo(bob, lobby): Courier.move(lobby, c4), Courier.move(c4, c5), Courier.move(c5, c6),"
                        + " Courier.move(c6, ward2), Courier.guide(bob, ward2, c6), Courier.guide(bob, c6, c5),"
                        + " Courier.guide(bob, c5, c4), Courier.guide(bob, c4, lobby), Courier.startFollowing(bob, lobby)",
                "goal FollowedTo(bob, lobby) satisfied",
                "task Follow(bob, lobby) completed"), milestones(run));
        allActionsSucceeded(run);
        assertEquals("lobby", h.sim().person("bob").room().map(Room::name).orElse("none"));
        assertEquals("lobby", h.courier().robot().room().map(Room::name).orElse("none"));

        // guided from ward 2, not carried off: Bob stayed close behind the robot from the first guide to the last
        List<PlatformLog.Entry> guides = run.platform().stream().filter(e -> e.call().startsWith("guide(bob")).toList();
        assertEquals(4, guides.size(), () -> log(run));
        double from = guides.get(0).start();
        double to = guides.get(guides.size() - 1).time();
        Trace trace = h.sim().trace();
        int bob = trace.personNames().indexOf("bob");
        double farthest = 0;
        int frames = 0;
        for (TraceFrame f : trace.frames()) {
            if (f.time() >= from && f.time() <= to) {
                farthest = Math.max(farthest, Math.hypot(f.robotX()[0] - f.personX()[bob], f.robotY()[0] - f.personY()[bob]));
                frames++;
            }
        }
        assertTrue(frames > 600, "Bob was guided for " + frames + " frames");
        assertTrue(farthest < 4, "Bob was at most " + farthest + " m from the robot");
        TracePicture.writePng(h.sim(), PICTURES.resolve("follow.png"));
    }
}
