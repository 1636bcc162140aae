package org.triad.planner;

import java.util.Locale;

/**
 * What grounding may create in the memory the JVM was given, and the timeout while it runs. Sizes are
 * estimated before anything is instantiated (free parameters, quantifiers over objects), so a task
 * too large ends in one line naming what and how many ({@link PlanningLimitException}) instead of an
 * {@code OutOfMemoryError} minutes later; the timeout is checked while the fixpoint runs
 * ({@link GroundingTimeoutException}). The deadline is per thread, set by the engine around grounding.
 */
final class GroundingLimits {
    /**
     * Heap per ground action, all told (the action, its binding key, its fact arrays, the search
     * task's and the heuristics' rows): a conservative figure, so a refusal means the task would not fit.
     */
    static final long BYTES_PER_ACTION = 600;
    /** Heap per binding of quantified variables while a formula is expanded (a small map). */
    static final long BYTES_PER_BINDING = 200;
    /** Checking the clock on every step would cost more than the steps. */
    private static final int CLOCK_EVERY = 1024;

    private static final ThreadLocal<Clock> CLOCK = ThreadLocal.withInitial(Clock::new);

    private GroundingLimits() { }

    /**
     * The timeout of the grounding running on this thread: fetched once per phase and ticked in its
     * loops (a thread-local look-up per step would cost the hospital's warm goals measurably).
     */
    static final class Clock {
        private long deadline = Long.MAX_VALUE;
        private int steps;

        /** Throws {@link GroundingTimeoutException} once the deadline has passed (looks at the clock every so often). */
        void tick() {
            if (++steps % CLOCK_EVERY == 0 && deadline != Long.MAX_VALUE && System.nanoTime() > deadline) {
                throw new GroundingTimeoutException();
            }
        }
    }

    /** This thread's grounding clock. */
    static Clock clock() {
        return CLOCK.get();
    }

    /** Runs {@code grounding} with the timeout checked at {@code deadlineNanos} ({@link System#nanoTime()}). */
    static <T> T withDeadline(long deadlineNanos, java.util.function.Supplier<T> grounding) {
        Clock c = CLOCK.get();
        long saved = c.deadline;
        c.deadline = deadlineNanos;
        try {
            return grounding.get();
        } finally {
            c.deadline = saved;
        }
    }

    /** Ground actions the heap can hold. */
    static long maxActions() {
        return Math.max(1000, Runtime.getRuntime().maxMemory() / BYTES_PER_ACTION);
    }

    /** Bindings of quantified variables one expansion may build. */
    static long maxBindings() {
        return Math.max(1000, Runtime.getRuntime().maxMemory() / BYTES_PER_BINDING / 4);
    }

    /** log10 of the number of combinations of these domain sizes (exact enough for any count). */
    static double log10Combinations(int... sizes) {
        double l = 0;
        for (int n : sizes) {
            if (n == 0) return Double.NEGATIVE_INFINITY;
            l += Math.log10(n);
        }
        return l;
    }

    /** Refuses {@code what} when its count (as log10) exceeds {@code limit}. */
    static void check(String what, double log10Count, long limit, String why) {
        if (log10Count <= Math.log10(limit)) return;
        throw new PlanningLimitException("grounding would create " + approx(log10Count) + " " + what + " (" + why
                + "): more than the memory given holds (" + (Runtime.getRuntime().maxMemory() >> 20) + " MB, about "
                + approx(Math.log10(limit)) + ")");
    }

    /** Domain sizes as a reader wants them: {@code 1,000 objects each} or {@code 3 × 40 objects}. */
    static String objects(int[] sizes) {
        boolean same = java.util.Arrays.stream(sizes).distinct().count() <= 1;
        if (same && sizes.length > 1) return approx(Math.log10(Math.max(1, sizes[0]))) + " objects each";
        return java.util.Arrays.stream(sizes).mapToObj(n -> approx(Math.log10(Math.max(1, n))))
                .collect(java.util.stream.Collectors.joining(" × ")) + " objects";
    }

    /** A count written as {@code 8·10⁹} (or in full below a million), from its log10. */
    static String approx(double log10) {
        if (log10 < 6) return String.format(Locale.ROOT, "%,d", Math.round(Math.pow(10, log10)));
        int exp = (int) Math.floor(log10);
        long mantissa = Math.round(Math.pow(10, log10 - exp));
        if (mantissa == 10) {
            mantissa = 1;
            exp++;
        }
        return mantissa + "·10" + superscript(exp);
    }

    private static String superscript(int n) {
        String digits = "⁰¹²³⁴⁵⁶⁷⁸⁹";
        StringBuilder sb = new StringBuilder();
        for (char c : Integer.toString(n).toCharArray()) sb.append(digits.charAt(c - '0'));
        return sb.toString();
    }
}
