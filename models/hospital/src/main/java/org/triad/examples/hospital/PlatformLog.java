package org.triad.examples.hospital;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.function.Consumer;

import org.triad.sim.ActionResult;

/**
 * What the robot and the world implementations did on the simulator, with the simulator's reasons:
 * RefArc only learns that an action failed, this log says why (DOOR_CLOSED, PATH_BLOCKED, ...).
 */
public final class PlatformLog {
    /**
     * One call of a model action or of a simulator activity it used.
     *
     * @param start   virtual time at its start, s
     * @param time    virtual time at its end, s
     * @param call    the model action or simulator activity
     * @param failure the simulator's failure name, "REFUSED" when the implementation itself declined the call or judged its
     *                outcome wrong (robot not at the start, door known closed, person not at the goal), or null on success
     */
    public record Entry(double start, double time, String call, boolean success, String failure, String detail) {
        @Override
        public String toString() {
            return String.format(Locale.ROOT, "[%7.2f s] %s %s%s", time, call,
                    success ? "ok" : "FAILED " + failure, detail == null || detail.isEmpty() ? "" : ": " + detail);
        }
    }

    private final List<Entry> entries = new ArrayList<>();
    private final List<Consumer<? super Entry>> observers = new ArrayList<>();

    void add(ActionResult r) {
        add(new Entry(r.startTime(), r.endTime(), r.action(), r.success(), r.success() ? null : r.failure().name(), r.message()));
    }

    void refused(double time, String call, String why) {
        add(new Entry(time, time, call, false, "REFUSED", why));
    }

    /** A call that the building could not carry out, e.g. {@code LIFT_FAULT} for a lift stopped between floors. */
    void failed(double time, String call, String failure, String why) {
        add(new Entry(time, time, call, false, failure, why));
    }

    private void add(Entry e) {
        entries.add(e);
        observers.forEach(o -> o.accept(e));
    }

    public void observe(Consumer<? super Entry> observer) {
        observers.add(Objects.requireNonNull(observer, "observer"));
    }

    public List<Entry> entries() {
        return List.copyOf(entries);
    }

    /** The most recent call's failure with its reason, e.g. {@code DOOR_CLOSED: ...}, or empty if it succeeded. */
    public java.util.Optional<String> lastFailure() {
        if (entries.isEmpty() || entries.get(entries.size() - 1).success()) {
            return java.util.Optional.empty();
        }
        Entry e = entries.get(entries.size() - 1);
        return java.util.Optional.of(e.failure() + (e.detail() == null || e.detail().isEmpty() ? "" : ": " + e.detail()));
    }

    /** Failures whose simulator reason is {@code failure} (e.g. "DOOR_CLOSED"). */
    public List<Entry> failures(String failure) {
        return entries.stream().filter(e -> failure.equals(e.failure())).toList();
    }
}
