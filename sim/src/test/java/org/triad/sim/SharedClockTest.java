package org.triad.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;

/** One simulation, one clock, robots commanded from several threads at once; contacts between robots. */
class SharedClockTest {

    @Test
    void robotsDrivenFromTwoThreadsMoveAtTheSameTimeUnderOneClock() throws Exception {
        Simulation sim = Simulation.builder(Scenes.PLAN).seed(1).recordTrace(false).build();
        Robot a = sim.addRobot("a", "corridorWest", RobotSpec.defaults());
        Robot b = sim.addRobot("b", "corridorEast", RobotSpec.defaults());
        // paced (20x real time), so that the moves last several of the waiting thread's 50 ms slices: as
        // fast as possible they may end within the first slice, and the hook never has a turn
        try (SimulationClock clock = SimulationClock.start(sim, 20.0)) {
            assertThrows(IllegalStateException.class, sim::step, "only the clock steps");
            AtomicInteger hooked = new AtomicInteger();
            CompletableFuture<ActionResult> east = CompletableFuture.supplyAsync(() -> {
                clock.whileWaiting(hooked::incrementAndGet);
                return a.moveTo("corridorEast");
            });
            CompletableFuture<ActionResult> west = CompletableFuture.supplyAsync(() -> b.moveTo("corridorWest"));
            ActionResult e = east.get(120, TimeUnit.SECONDS);
            ActionResult w = west.get(120, TimeUnit.SECONDS);
            assertTrue(e.success(), e::toString);
            assertTrue(w.success(), w::toString);
            assertTrue(e.startTime() < w.endTime() && w.startTime() < e.endTime(), "the moves overlapped in virtual time");
            assertTrue(hooked.get() > 0, "the waiting thread's hook ran while it waited");
            double t = clock.call(Simulation::time);
            boolean arrived = clock.call(s -> s.robot("a").isAt("corridorEast", 0.3));
            assertTrue(arrived);
            assertTrue(t >= e.endTime());
            clock.submit(s -> s.robot("nobody")); // a bad command: printed, the clock goes on
            CompletableFuture<Boolean> queued = new CompletableFuture<>();
            clock.submit(s -> queued.complete(s.robots().size() == 2));
            assertTrue(queued.get(60, TimeUnit.SECONDS), "a queued command runs on the clock thread");
            assertTrue(clock.isRunning());
        }
    }

    @Test
    void aPausedRobotHoldsStillAndItsMoveResumesWithoutTimingOut() throws Exception {
        Simulation sim = Simulation.builder(Scenes.PLAN).seed(1).recordTrace(false).build();
        Robot r = sim.addRobot("r", "corridorWest", RobotSpec.defaults().withTimeouts(5, 2));
        try (SimulationClock clock = SimulationClock.start(sim, SimulationClock.AS_FAST_AS_POSSIBLE)) {
            PendingAction move = r.startMoveTo("corridorEast");
            while (clock.call(s -> s.robot("r").position().x()) <= 3) {
                Thread.sleep(2);
            }
            r.setPaused(true);
            Vec2 held = clock.call(s -> s.robot("r").position());
            double from = clock.call(Simulation::time);
            while (clock.call(Simulation::time) < from + 10) { // longer than the blocked timeout (2 s)
                Thread.sleep(5);
            }
            assertEquals(held.x(), clock.call(s -> s.robot("r").position().x()), 1e-9, "paused: holds still");
            assertFalse(move.isDone());
            r.setPaused(false);
            ActionResult done = move.await();
            assertTrue(done.success(), done::toString);
        }
    }

    @Test
    void twoRobotsThatTouchAreOneContactWithWhoWhereAndWhen() {
        Simulation sim = Scenes.sim(1);
        Robot a = sim.addRobot("a", new Vec2(6, 6.2), RobotSpec.defaults());
        sim.addRobot("b", new Vec2(6.9, 6.2), RobotSpec.defaults());
        List<Contact> heard = new ArrayList<>();
        sim.onContact(heard::add);
        a.body.setLinearVelocity(1, 0); // pushed towards b: braking at 0.8 m/s^2 needs 0.62 m, the gap is 0.3 m
        sim.runFor(2);
        assertEquals(1, heard.size(), heard::toString);
        Contact c = heard.get(0);
        assertEquals("a", c.first());
        assertEquals("b", c.second());
        assertTrue(c.time() > 0 && c.time() < 1, c::toString);
        assertEquals(6.2, c.position().y(), 0.05);
        assertTrue(c.toString().startsWith("contact a b at ("), c::toString);
        assertEquals(heard, sim.contacts());
    }
}
