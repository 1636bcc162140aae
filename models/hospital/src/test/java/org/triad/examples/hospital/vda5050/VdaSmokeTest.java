package org.triad.examples.hospital.vda5050;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import org.junit.jupiter.api.Test;
import org.triad.refarc.RefArcRun;
import org.triad.vda5050.broker.MosquittoBroker;
import org.triad.vda5050.master.MasterControl;
import org.triad.vda5050.master.VdaTimeouts;
import org.triad.vda5050.mqtt.ConformanceMonitor;

import generated.hospital.tasks.CollectAndDeliver;

class VdaSmokeTest {
    @Test
    void delivery() {
        List<String> log = new CopyOnWriteArrayList<>();
        try (MosquittoBroker broker = MosquittoBroker.start(Path.of("target/mosquitto/smoke"));
                ConformanceMonitor monitor = ConformanceMonitor.on(broker.url());
                SimulatedAgv agv = new SimulatedAgv(broker.url(), "courier-1", 42, 50, Path.of("target/vda-pictures"), log::add).start();
                MasterControl master = MasterControl.connect(broker.url(), VdaTimeouts.defaults(), log::add)) {
            VdaHospital h = new VdaHospital(master, "courier-1");
            RefArcRun run = h.run(new CollectAndDeliver(h.objects().item("gauze"), h.objects().room("storage"), h.objects().room("ward1")),
                    s -> System.out.println(s));
            log.forEach(System.out::println);
            System.out.println(monitor.counts());
            assertEquals(RefArcRun.Outcome.COMPLETED, run.outcome());
            assertTrue(monitor.violations().isEmpty(), monitor.violations().toString());
            assertTrue(agv.statesSent() > 0);
        }
    }
}
