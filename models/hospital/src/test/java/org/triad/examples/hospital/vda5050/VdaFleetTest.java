package org.triad.examples.hospital.vda5050;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;

import org.junit.jupiter.api.Test;
import org.triad.refarc.RefArcRun;
import org.triad.runtime.app.TaskInstance;
import org.triad.vda5050.broker.MosquittoBroker;
import org.triad.vda5050.master.MasterControl;
import org.triad.vda5050.master.VdaTimeouts;
import org.triad.vda5050.mqtt.ConformanceMonitor;

import generated.hospital.tasks.CollectAndDeliver;
import generated.hospital.tasks.GoTo;

/** One master process serving three robots on one broker, each with its own RefArc and topics, tasks at the same time. */
class VdaFleetTest {
    private record Timed(RefArcRun run, long start, long end) {
    }

    @Test
    void threeRobotsRunTheirTasksAtTheSameTime() throws Exception {
        List<String> log = new CopyOnWriteArrayList<>();
        List<SimulatedAgv> agvs = new ArrayList<>();
        Path dir = Path.of("target", "vda5050", "fleet");
        ExecutorService pool = Executors.newFixedThreadPool(3);
        try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"));
                ConformanceMonitor monitor = ConformanceMonitor.on(broker.url())) {
            // timeouts for a loaded machine: this test is about robots working at the same time, not about silence
            try (MasterControl master = MasterControl.connect(broker.url(), new VdaTimeouts(30, 10, 120, 5), log::add)) {
                for (int i = 1; i <= 3; i++) {
                    agvs.add(new SimulatedAgv(broker.url(), "courier-" + i, i, 20, dir, log::add).start());
                }
                List<Future<Timed>> runs = new ArrayList<>();
                for (int i = 1; i <= 3; i++) {
                    VdaHospital h = new VdaHospital(master, "courier-" + i);
                    TaskInstance task = switch (i) {
                        case 1 -> new GoTo(h.objects().room("ward3"));
                        case 2 -> new GoTo(h.objects().room("storage"));
                        default -> new CollectAndDeliver(h.objects().item("bandage"), h.objects().room("storage"), h.objects().room("xray"));
                    };
                    runs.add(pool.submit(() -> {
                        long start = System.nanoTime();
                        RefArcRun run = h.run(task, s -> { });
                        return new Timed(run, start, System.nanoTime());
                    }));
                }
                List<Timed> done = new ArrayList<>();
                for (Future<Timed> f : runs) {
                    done.add(f.get());
                }
                for (Timed t : done) {
                    assertEquals(RefArcRun.Outcome.COMPLETED, t.run().outcome(), t.run().log() + "\n" + log);
                }
                long latestStart = done.stream().mapToLong(Timed::start).max().orElseThrow();
                long earliestEnd = done.stream().mapToLong(Timed::end).min().orElseThrow();
                assertTrue(latestStart < earliestEnd, "the three tasks overlapped in time");
                assertEquals("ward3", agvStateLastNode(master, "courier-1"));
                assertEquals("storage", agvStateLastNode(master, "courier-2"));
                assertEquals("xray", agvStateLastNode(master, "courier-3"));
            } finally {
                agvs.forEach(SimulatedAgv::close);
                pool.shutdownNow();
            }
            assertEquals(List.of(), monitor.violations());
        }
    }

    private static String agvStateLastNode(MasterControl master, String serial) {
        return master.agv(serial).state().orElseThrow().lastNodeId();
    }
}
