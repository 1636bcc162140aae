package org.triad.sim;

import java.util.Locale;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Consumer;
import java.util.function.Function;

/**
 * The one clock of a shared simulation (a building hosting many robots): a thread of its own steps the
 * {@link Simulation}, paced at {@code speed} virtual seconds per wall-clock second, or as fast as the
 * machine allows ({@link #AS_FAST_AS_POSSIBLE}). Once a clock runs, only it steps; other threads command
 * and read the simulation through it:
 * <ul>
 * <li>{@link #call(Function)} / {@link #run(Consumer)} run a piece of code under the clock's lock, between
 * two steps (the lock is fair, so callers queue in arrival order and the clock never starves them);</li>
 * <li>{@link #submit(Consumer)} queues a command that the clock thread runs before its next step, without
 * waiting (for MQTT callback threads);</li>
 * <li>a robot's blocking activity ({@link Robot#moveTo(String)}, {@link Robot#pick(String)}, ...) called from
 * any thread starts under the lock and then waits, releasing the lock, until the clock has stepped it to its
 * end. So many threads can each drive their robot at the same time in the same corridors.</li>
 * </ul>
 * Reading the simulation (a robot's position, an item's holder) from another thread is only consistent
 * inside {@link #call(Function)}. The lock is reentrant: a blocking activity inside {@code call} is fine.
 */
public final class SimulationClock implements AutoCloseable {
    /** Speed that steps without pausing. */
    public static final double AS_FAST_AS_POSSIBLE = Double.POSITIVE_INFINITY;
    /** Wall-clock nanoseconds a waiting thread sleeps before it runs its {@link #whileWaiting(Runnable) hook}. */
    private static final long WAIT_SLICE_NANOS = 50_000_000L;
    /** Steps the clock takes at most per turn of its lock when it is behind. */
    private static final int MAX_STEPS_PER_TURN = 8;
    /** How far ahead of the wall clock virtual time may run before the clock sleeps. */
    private static final long SLEEP_NANOS = 3_000_000L;
    /** How far behind the clock catches up before it gives the lag up. */
    private static final long MAX_LAG_NANOS = 10_000_000_000L;

    private final Simulation sim;
    private final double speed;
    private final ReentrantLock lock = new ReentrantLock(true);
    private final Condition activityDone = lock.newCondition();
    private final ConcurrentLinkedQueue<Consumer<Simulation>> commands = new ConcurrentLinkedQueue<>();
    private final ThreadLocal<Runnable> waitingHooks = new ThreadLocal<>();
    private final Thread thread;
    private final long wallStart;
    private final double simStart;
    private volatile boolean running = true;
    private volatile Throwable failure;
    private long paceWall;
    private double paceSim;
    private int stepsSinceYield;

    private SimulationClock(Simulation sim, double speed, String name) {
        this.sim = sim;
        this.speed = speed;
        this.thread = new Thread(this::loop, name);
        this.thread.setDaemon(true);
        this.wallStart = System.nanoTime();
        this.simStart = sim.time();
        this.paceWall = wallStart;
        this.paceSim = simStart;
    }

    /**
     * Starts stepping {@code sim} in a thread of its own.
     *
     * @param speed virtual seconds per wall-clock second (&gt; 0), or {@link #AS_FAST_AS_POSSIBLE}
     * @throws IllegalArgumentException for a speed that is not positive
     * @throws IllegalStateException if the simulation already has a clock
     */
    public static SimulationClock start(Simulation sim, double speed) {
        Checks.notNull("simulation", sim);
        if (!(speed > 0)) {
            throw new IllegalArgumentException("speed is a positive factor (virtual s per wall s) or AS_FAST_AS_POSSIBLE, not " + speed);
        }
        SimulationClock clock = new SimulationClock(sim, speed, "sim-clock");
        sim.attach(clock);
        clock.thread.start();
        return clock;
    }

    /** The simulation this clock steps. */
    public Simulation simulation() {
        return sim;
    }

    /** Virtual seconds per wall-clock second asked for ({@link #AS_FAST_AS_POSSIBLE} if unpaced). */
    public double speed() {
        return speed;
    }

    /** Virtual seconds passed per wall-clock second since the clock started (what the machine achieved). */
    public double achievedSpeed() {
        double wall = (System.nanoTime() - wallStart) / 1e9;
        return wall <= 0 ? 0 : (sim.time() - simStart) / wall;
    }

    /** Whether the clock still steps (false after {@link #close()} or after a step threw; see {@link #failure()}). */
    public boolean isRunning() {
        return running && thread.isAlive();
    }

    /** What a step threw, if the clock stopped because of it. */
    public java.util.Optional<Throwable> failure() {
        return java.util.Optional.ofNullable(failure);
    }

    /**
     * Runs {@code f} under the clock's lock, between two steps, and returns its value. It may start blocking
     * robot activities (they release the lock while they wait).
     *
     * @throws IllegalStateException if called from a scripted event or step listener (the clock thread)
     */
    public <T> T call(Function<Simulation, T> f) {
        Checks.notNull("function", f);
        requireNotClockThread();
        lock.lock();
        try {
            return f.apply(sim);
        } finally {
            lock.unlock();
        }
    }

    /** {@link #call(Function)} without a value. */
    public void run(Consumer<Simulation> c) {
        Checks.notNull("command", c);
        call(s -> {
            c.accept(s);
            return null;
        });
    }

    /**
     * Queues {@code c} to run on the clock thread before its next step; returns at once. It must not block (a blocking
     * robot activity there throws); an exception it throws is printed and the clock goes on.
     */
    public void submit(Consumer<Simulation> c) {
        commands.add(Checks.notNull("command", c));
    }

    /**
     * Sets what the calling thread does while one of its blocking robot activities waits for the clock: run
     * about every 50 ms of wall-clock time, under the lock (so it may read and command the simulation, but not
     * start another blocking activity of the same robot). Null removes it. A VDA 5050 AGV handles the messages
     * that arrive while it drives there.
     */
    public void whileWaiting(Runnable hook) {
        if (hook == null) {
            waitingHooks.remove();
        } else {
            waitingHooks.set(hook);
        }
    }

    /** Called by a blocking activity: waits (lock released) until {@code pending} is done. */
    ActionResult await(PendingAction pending) {
        requireNotClockThread();
        lock.lock();
        try {
            while (!pending.isDone()) {
                if (!isRunning()) {
                    throw new IllegalStateException("the simulation clock has stopped"
                            + failure().map(t -> ": a step threw " + t).orElse(""));
                }
                activityDone.awaitNanos(WAIT_SLICE_NANOS);
                Runnable hook = waitingHooks.get();
                if (hook != null && !pending.isDone()) {
                    hook.run();
                }
            }
            return pending.result().orElseThrow();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while waiting for the simulation", e);
        } finally {
            lock.unlock();
        }
    }

    /** Starts {@code r}'s activity under the lock (from any thread). */
    PendingAction start(java.util.function.Supplier<PendingAction> r) {
        requireNotClockThread();
        lock.lock();
        try {
            return r.get();
        } finally {
            lock.unlock();
        }
    }

    /** Called under the lock when an activity ends: wakes the threads waiting for one. */
    void activityEnded() {
        activityDone.signalAll();
    }

    boolean isClockThread() {
        return Thread.currentThread() == thread;
    }

    private void requireNotClockThread() {
        if (isClockThread()) {
            throw new IllegalStateException("blocking simulation calls are not allowed on the clock thread (scripted events, step listeners)");
        }
    }

    private void loop() {
        try {
            while (running) {
                lock.lock();
                try {
                    Consumer<Simulation> c;
                    while ((c = commands.poll()) != null) {
                        try {
                            c.accept(sim);
                        } catch (RuntimeException e) {
                            // a bad command is its sender's fault: the building goes on
                            System.err.println("simulation clock: a queued command failed at " + String.format(Locale.ROOT, "%.2f s", sim.time())
                                    + ": " + e);
                        }
                    }
                    // behind the wall clock, catch up a few steps per turn of the lock: on a loaded machine every
                    // hand-over of the lock costs a trip through the scheduler
                    int n = 0;
                    do {
                        sim.step();
                    } while (++n < MAX_STEPS_PER_TURN && behind());
                } finally {
                    lock.unlock();
                }
                pace();
            }
        } catch (Throwable t) {
            failure = t;
            running = false;
            System.err.println("simulation clock stopped at " + String.format(Locale.ROOT, "%.2f s", sim.time()) + ": " + t);
        } finally {
            lock.lock();
            try {
                activityDone.signalAll();
            } finally {
                lock.unlock();
            }
        }
    }

    private boolean behind() {
        return !Double.isInfinite(speed) && System.nanoTime() > paceWall + (long) ((sim.time() - paceSim) / speed * 1e9);
    }

    /**
     * Sleeps while virtual time is ahead of {@code speed} x the wall clock by more than {@value #SLEEP_NANOS} ns (sleeping
     * after every 1.7 ms step would pay the scheduler's overshoot every time); steps without sleeping while behind, to
     * catch up; behind by more than {@value #MAX_LAG_NANOS} ns (a machine that cannot keep up), re-paces from now
     * rather than racing.
     */
    private void pace() {
        if (Double.isInfinite(speed)) {
            if ((++stepsSinceYield & 63) == 0) {
                Thread.yield();
            }
            return;
        }
        long due = paceWall + (long) ((sim.time() - paceSim) / speed * 1e9);
        long now = System.nanoTime();
        if (due - now > SLEEP_NANOS) {
            try {
                TimeUnit.NANOSECONDS.sleep(due - now);
            } catch (InterruptedException e) {
                running = false;
            }
        } else if (now - due > MAX_LAG_NANOS) {
            paceWall = now;
            paceSim = sim.time();
        }
    }

    /** Stops stepping (waiting activities then fail with an IllegalStateException); idempotent. */
    @Override
    public void close() {
        running = false;
        if (!isClockThread()) {
            thread.interrupt();
            try {
                thread.join(5000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    @Override
    public String toString() {
        return String.format(Locale.ROOT, "SimulationClock[%s, speed %s, achieved %.1fx]", sim, Double.isInfinite(speed) ? "max" : speed,
                achievedSpeed());
    }
}
