package org.triad.examples.hospital.vda5050;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

import org.junit.jupiter.api.Test;
import org.triad.building.traffic.Resource;
import org.triad.examples.hospital.HospitalFloor;
import org.triad.vda5050.broker.MosquittoBroker;
import org.triad.vda5050.devices.DeviceLink;
import org.triad.vda5050.master.DoorKeeper;
import org.triad.vda5050.master.MasterControl;
import org.triad.vda5050.master.RemoteAgv;
import org.triad.vda5050.master.RemoteAgv.EdgeAction;
import org.triad.vda5050.master.TrafficControl;

/**
 * The lift under traffic control, in one simulated two-floor building on a real Mosquitto: the ride between the landings
 * c7 and d1 is an edge of {@link HospitalTraffic}'s map in the lift's area (one robot), driven as the AGV's edge action
 * {@code ride}. Courier-1 rides up while courier-2 asks for the same way up: courier-2 waits, and rides once courier-1
 * is out of the cabin and off the landing. Never are both in the lift's area.
 */
class TrafficLiftTest {
    @Test
    void oneRidesTheOtherWaitsAndRidesNext() throws Exception {
        Path dir = Path.of("target", "vda5050", "trafficLift");
        List<String> log = new CopyOnWriteArrayList<>();
        try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"));
                AgvProcess building = AgvProcess.building(broker.url(), 2, 10, dir); // 10x: a ride still takes seconds of wall clock, courier-2 asks at once
                MasterControl master = MasterControl.connect(broker.url(), VdaFaultsTest.TEST_TIMEOUTS, log::add);
                DeviceLink keeperLink = DeviceLink.connect(broker.url(), "traffic-lift-keeper", log::add);
                DoorKeeper keeper = new DoorKeeper(keeperLink, HospitalTraffic.keptDoors(new HospitalFloor()), 30, log::add)) {
            RemoteAgv one = master.agv("courier-1");
            RemoteAgv two = master.agv("courier-2");
            assertTrue(one.awaitOnline() && two.awaitOnline(), building.output());
            TrafficControl traffic = new TrafficControl(HospitalTraffic.map(new HospitalFloor()), 300, log::add).keepDoors(keeper);
            Resource lift = traffic.read(t -> t.map().area(HospitalFloor.LIFT).orElseThrow());
            assertEquals(HospitalTraffic.LIFT_CAPACITY, lift.capacity());
            int upper = traffic.read(t -> t.map().area(HospitalTraffic.UPPER_FLOOR).orElseThrow().capacity());
            assertEquals(3, upper, "the upper floor's four places (d1, d2, ward 4, ward 5) admit three robots");
            // the east corridor's lane c3-c6 runs over the landing c7: a robot waiting for the lift there blocks it
            Resource passingC7 = traffic.read(t -> t.map().area(HospitalTraffic.PASSING + "c7").orElseThrow());
            assertEquals(1, passingC7.capacity());
            boolean laneAndLanding = traffic.read(t -> t.map().areasOf(t.map().edge("c3", "c6").orElseThrow()).contains(passingC7)
                    && t.map().areasOf(t.map().node("c7")).contains(passingC7) && t.map().isStop("c7"));
            assertTrue(laneAndLanding, "the lane c3-c6 and the landing c7 are one place for one robot, where robots may still wait");

            assertTrue(one.driveRoute(AgvProcess.outOfTheLobby(one, "c4", "c5", "c6", "c7"), traffic), one.lastFailure() + "\n" + log);
            assertTrue(two.driveRoute(AgvProcess.outOfTheLobby(two, "c4", "c5", "c6"), traffic), two.lastFailure() + "\n" + log);

            // who holds the lift, and whether courier-2 waits meanwhile, sampled while they ride
            List<Set<String>> holders = new CopyOnWriteArrayList<>();
            AtomicBoolean twoWaitedWhileOneHeldTheLift = new AtomicBoolean();
            AtomicBoolean sampling = new AtomicBoolean(true);
            Thread sampler = new Thread(() -> {
                while (sampling.get()) {
                    traffic.read(t -> {
                        Set<String> h = Set.copyOf(t.holders(lift));
                        if (holders.isEmpty() || !holders.get(holders.size() - 1).equals(h)) {
                            holders.add(h);
                        }
                        if (h.equals(Set.of(one.name())) && t.waiting(two.name()).isPresent()) {
                            twoWaitedWhileOneHeldTheLift.set(true);
                        }
                        return null;
                    });
                    sleep(2);
                }
            }, "lift-sampler");
            sampler.start();
            EdgeAction ride = new EdgeAction("ride", java.util.Map.of("liftId", HospitalFloor.LIFT));
            List<EdgeAction> upAndOn = new ArrayList<>();
            upAndOn.add(ride);
            upAndOn.add(null);
            CompletableFuture<Boolean> first = CompletableFuture.supplyAsync(() -> one.driveRoute(List.of("c7", "d1", "d2"), traffic, upAndOn));
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (!traffic.read(t -> t.holders(lift).contains(one.name()))) {
                assertTrue(System.nanoTime() < deadline, "courier-1 never got the lift: " + log);
                Thread.sleep(5);
            }
            List<EdgeAction> onAndUp = new ArrayList<>();
            onAndUp.add(null);
            onAndUp.add(ride);
            CompletableFuture<Boolean> second = CompletableFuture.supplyAsync(() -> two.driveRoute(List.of("c6", "c7", "d1"), traffic, onAndUp));
            assertTrue(first.get(300, TimeUnit.SECONDS), one.lastFailure() + "\n" + log + "\n" + building.output());
            assertTrue(second.get(300, TimeUnit.SECONDS), two.lastFailure() + "\n" + log + "\n" + building.output());
            sampling.set(false);
            sampler.join(10_000);

            assertEquals("d2", one.state().orElseThrow().lastNodeId(), "courier-1 rode up and drove on");
            assertEquals("d1", two.state().orElseThrow().lastNodeId(), "courier-2 rode up next");
            assertTrue(twoWaitedWhileOneHeldTheLift.get(), "courier-2 waited while courier-1 held the lift: " + holders + "\n" + log);
            assertTrue(holders.stream().allMatch(h -> h.size() <= lift.capacity()), "never both in the lift: " + holders);
            List<String> riders = holders.stream().filter(h -> !h.isEmpty()).map(h -> h.iterator().next()).distinct().toList();
            assertEquals(List.of(one.name(), two.name()), riders, "courier-1 rode first, courier-2 next: " + holders);
            assertTrue(building.lines("contact courier-").isEmpty(), building.output());
        }
    }

    private static void sleep(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
