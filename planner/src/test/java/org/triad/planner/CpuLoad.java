package org.triad.planner;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * Busy threads beside a test, two per core, for as long as it is open: a plan that work budgets decide
 * comes out the same with them as without.
 */
final class CpuLoad implements AutoCloseable {
    private final AtomicBoolean stop = new AtomicBoolean();
    private final List<Thread> burners = new ArrayList<>();

    private CpuLoad() {
        for (int i = 0; i < 2 * Runtime.getRuntime().availableProcessors(); i++) {
            Thread t = new Thread(() -> {
                long x = 1;
                while (!stop.get()) x = x * 6364136223846793005L + 1442695040888963407L;
                if (x == 42) System.out.print(""); // keeps the loop from being optimised away
            }, "cpu-load-" + i);
            t.setDaemon(true);
            t.start();
            burners.add(t);
        }
    }

    static CpuLoad start() {
        return new CpuLoad();
    }

    @Override
    public void close() throws InterruptedException {
        stop.set(true);
        for (Thread t : burners) t.join();
    }
}
