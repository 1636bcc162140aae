package org.triad.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The benchmark's crowded delivery completes for several seeds (moves retried as an application would). */
class DeliveryScenarioTest {

    @ParameterizedTest
    @ValueSource(longs = {11, 12, 13})
    void crowdedDeliveryCompletes(long seed) {
        Simulation sim = DeliveryBenchmark.deliver(seed, false);
        assertEquals("room2", sim.item("item1").room().orElseThrow().name());
        assertEquals("room5", sim.item("item2").room().orElseThrow().name());
        assertTrue(sim.robot("robot").isAt("corridorWest", 0.1));
        assertTrue(sim.time() < 200, "took " + sim.time() + " s");
        assertTrue(sim.trace().frames().isEmpty(), "trace off records no frames");
        assertTrue(sim.trace().events().size() >= 10, "events are recorded even with frames off");
    }
}
