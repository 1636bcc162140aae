package org.triad.tests.hospital;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.triad.examples.hospital.HospitalObjects;
import org.triad.examples.hospital.HospitalRun;
import org.triad.examples.hospital.HospitalSimulation;
import org.triad.sim.TraceFrame;

import generated.hospital.tasks.CollectAndDeliver;

/** The same seed and scenario give the same run through RefArc: the same statuses and, frame by frame, the same trajectory. */
class HospitalSimulationDeterminismTest {

    private static HospitalSimulation blockedDelivery(long seed) {
        HospitalSimulation h = new HospitalSimulation(seed);
        // people in the corridor make the run depend on contact physics and steering, not only on straight driving
        h.sim().at(33).blockSegment("c1", "c2", 3, 30);
        HospitalObjects o = h.objects();
        HospitalRun run = h.run(new CollectAndDeliver(o.item("gauze"), o.room("storage"), o.room("ward1")));
        assertTrue(run.completed(), () -> HospitalRunAssertions.log(run));
        return h;
    }

    @Test
    void theSameSeedGivesTheSameTrajectory() {
        HospitalSimulation first = blockedDelivery(17);
        HospitalSimulation second = blockedDelivery(17);

        assertEquals(first.platformLog().entries(), second.platformLog().entries());
        List<TraceFrame> a = first.sim().trace().frames();
        List<TraceFrame> b = second.sim().trace().frames();
        assertEquals(a.size(), b.size());
        assertTrue(a.size() > 3000, "a long run: " + a.size() + " frames");
        for (int i = 0; i < a.size(); i++) {
            String at = "frame " + i;
            assertEquals(a.get(i).time(), b.get(i).time(), at);
            assertArrayEquals(a.get(i).robotX(), b.get(i).robotX(), at);
            assertArrayEquals(a.get(i).robotY(), b.get(i).robotY(), at);
            assertArrayEquals(a.get(i).robotHeading(), b.get(i).robotHeading(), at);
            assertArrayEquals(a.get(i).personX(), b.get(i).personX(), at);
            assertArrayEquals(a.get(i).personY(), b.get(i).personY(), at);
            assertArrayEquals(a.get(i).itemX(), b.get(i).itemX(), at);
            assertArrayEquals(a.get(i).doorOpen(), b.get(i).doorOpen(), at);
        }
    }
}
