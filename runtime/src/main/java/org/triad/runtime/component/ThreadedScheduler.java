package org.triad.runtime.component;

import java.time.Duration;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * Components run concurrently on a shared thread pool; each component handles its messages
 * serially, in arrival order. Activities run on a separate pool so long work never occupies a
 * component thread.
 */
public final class ThreadedScheduler extends Scheduler {
    /** Messages a component handles before it yields its thread to other components. */
    private static final int BATCH = 64;

    private final ExecutorService components;
    private final ExecutorService workers;
    private final Object idleLock = new Object();
    private int outstanding;

    ThreadedScheduler(int threads) {
        if (threads < 1) {
            throw new IllegalArgumentException("a threaded scheduler needs at least one thread, not " + threads);
        }
        components = Executors.newFixedThreadPool(threads, daemons("triad-component-"));
        workers = Executors.newCachedThreadPool(daemons("triad-activity-"));
    }

    private static ThreadFactory daemons(String prefix) {
        AtomicInteger n = new AtomicInteger();
        return r -> {
            Thread t = new Thread(r, prefix + n.incrementAndGet());
            t.setDaemon(true);
            return t;
        };
    }

    /** Waits until no message is queued or being handled and no activity runs. Returns false on timeout. */
    public boolean awaitIdle(Duration timeout) throws InterruptedException {
        long deadline = System.nanoTime() + timeout.toNanos();
        synchronized (idleLock) {
            while (outstanding > 0) {
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    return false;
                }
                TimeUnit.NANOSECONDS.timedWait(idleLock, left);
            }
            return true;
        }
    }

    private void begin() {
        synchronized (idleLock) {
            outstanding++;
        }
    }

    private void end() {
        synchronized (idleLock) {
            if (--outstanding == 0) {
                idleLock.notifyAll();
            }
        }
    }

    @Override
    void enqueue(Envelope envelope) {
        begin();
        AtomicComponent c = envelope.target;
        c.mailbox.add(envelope);
        schedule(c);
    }

    private void schedule(AtomicComponent c) {
        if (c.scheduled.compareAndSet(false, true)) {
            try {
                components.execute(() -> drain(c));
            } catch (RejectedExecutionException closed) {
                // after close(), e.g. the result of an interrupted activity: nobody is left to handle it
                end();
            }
        }
    }

    private void drain(AtomicComponent c) {
        for (int i = 0; i < BATCH; i++) {
            Envelope e = c.mailbox.poll();
            if (e == null) {
                break;
            }
            try {
                c.process(e);
            } finally {
                end();
            }
        }
        c.scheduled.set(false);
        if (!c.mailbox.isEmpty()) {
            schedule(c);
        }
    }

    @Override
    void startActivity(Activity<?> activity) {
        begin();
        try {
            workers.execute(() -> {
                try {
                    activity.runOn(this);
                } finally {
                    end();
                }
            });
        } catch (RejectedExecutionException closed) {
            // after close(): the activity is not started
            end();
        }
    }

    /** Stops the threads; running activities are interrupted. */
    @Override
    public void close() {
        components.shutdownNow();
        workers.shutdownNow();
    }
}
