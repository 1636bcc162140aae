package org.triad.examples.hospital;

import java.util.List;

import org.triad.refarc.RefArcRun;

/**
 * One task run in the simulated hospital: what RefArc reported, what the platform did, and the
 * virtual and wall-clock time it took.
 *
 * @param simSeconds  virtual time the run advanced, s
 * @param wallSeconds wall-clock time of the run, s
 */
public record HospitalRun(RefArcRun refArc, List<PlatformLog.Entry> platform, double simSeconds, double wallSeconds) {
    public HospitalRun {
        platform = List.copyOf(platform);
    }

    public boolean completed() {
        return refArc.outcome() == RefArcRun.Outcome.COMPLETED;
    }

    /** Simulated seconds per wall-clock second. */
    public double realTimeFactor() {
        return simSeconds / wallSeconds;
    }
}
