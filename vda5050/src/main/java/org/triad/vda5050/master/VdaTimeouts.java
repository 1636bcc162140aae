package org.triad.vda5050.master;

/**
 * How long master control waits, in wall-clock seconds.
 *
 * @param onlineSeconds   for an AGV never heard from to come online before its first order fails
 * @param stateSeconds    without a state message while an order runs before the order fails (the AGV sends one at least every second)
 * @param actionSeconds   for one order or instant action to finish
 * @param reconnectGraceSeconds after an AGV's CONNECTIONBROKEN for it to come back ONLINE before its order fails
 */
public record VdaTimeouts(double onlineSeconds, double stateSeconds, double actionSeconds, double reconnectGraceSeconds) {
    public VdaTimeouts {
        for (double d : new double[] { onlineSeconds, stateSeconds, actionSeconds, reconnectGraceSeconds }) {
            if (!(d > 0) || Double.isInfinite(d)) {
                throw new IllegalArgumentException("timeouts are positive seconds, not " + d);
            }
        }
    }

    /** For robots in a building: 10 s to come online, 5 s of silence, 10 min per action, 3 s to reconnect. */
    public static VdaTimeouts defaults() {
        return new VdaTimeouts(10, 5, 600, 3);
    }
}
