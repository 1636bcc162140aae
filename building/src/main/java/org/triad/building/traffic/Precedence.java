package org.triad.building.traffic;

/**
 * What a robot's request asks of rule 3 when it would close a cycle of waits (see {@link ReservationTable#request(String,
 * java.util.List, Precedence)} and the module's README): a robot with precedence does not make way, the waiting robots of
 * the cycle without it do.
 */
public enum Precedence {
    /** An ordinary drive: it makes way when rule 3 says so. */
    PLAIN,
    /** The robot guides a person along the route: stepping aside would leave the person behind. */
    GUIDE,
    /**
     * The robot drives to charge below its reserve: every metre it drives out of the way is one it may not have, and a
     * robot whose battery runs empty stands where it is, in everybody's way, until it is charged.
     */
    URGENT;

    /** Whether a robot asking with this does not make way for plain robots. */
    public boolean overridesPlain() {
        return this != PLAIN;
    }
}
