package org.triad.runtime.component;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;

/**
 * Single-threaded scheduler for tests: one FIFO queue of messages for all components, processed on
 * the caller's thread in the order they were sent. Activities do not run by themselves: they wait
 * until the test runs them ({@link #runNextActivity()}, {@link #runToCompletion()}), so a test
 * controls exactly what happens while an activity is in progress.
 */
public final class DeterministicScheduler extends Scheduler {
    /** Bounds {@link #runToCompletion()} so a livelocked architecture fails the test instead of hanging it. */
    public static final int MAX_STEPS = 1_000_000;

    private final Deque<Envelope> queue = new ArrayDeque<>();
    private final Deque<Activity<?>> activities = new ArrayDeque<>();

    DeterministicScheduler() {
    }

    /** Handles queued messages (and those they cause) until the queue is empty; returns how many. Does not run activities. */
    public int runUntilIdle() {
        int n = 0;
        Envelope e;
        while ((e = poll()) != null) {
            e.target.process(e);
            if (++n > MAX_STEPS) {
                throw new IllegalStateException("no quiescence after " + MAX_STEPS + " messages: the architecture livelocks");
            }
        }
        return n;
    }

    /** Descriptions of the activities started but not run yet, oldest first. */
    public synchronized List<String> pendingActivities() {
        List<String> l = new ArrayList<>();
        activities.forEach(a -> l.add(a.toString()));
        return l;
    }

    /** Runs the oldest pending activity on this thread; its result is queued as a message. Returns false if none was pending. */
    public boolean runNextActivity() {
        Activity<?> a;
        synchronized (this) {
            a = activities.poll();
        }
        if (a == null) {
            return false;
        }
        a.runOn(this);
        return true;
    }

    /** Alternates {@link #runUntilIdle()} and {@link #runNextActivity()} until nothing is left to do. */
    public void runToCompletion() {
        int steps = 0;
        do {
            runUntilIdle();
            if (++steps > MAX_STEPS) {
                throw new IllegalStateException("no quiescence after " + MAX_STEPS + " activities: the architecture livelocks");
            }
        } while (runNextActivity());
    }

    private synchronized Envelope poll() {
        return queue.poll();
    }

    @Override
    synchronized void enqueue(Envelope envelope) {
        queue.add(envelope);
    }

    @Override
    synchronized void startActivity(Activity<?> activity) {
        activities.add(activity);
    }
}
