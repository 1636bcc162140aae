/**
 * The hospital over VDA 5050: {@link org.triad.examples.hospital.vda5050.SimulatedAgv} is a simulated
 * courier of the dyn4j hospital acting as a VDA 5050 AGV on a broker (its own process:
 * {@link org.triad.examples.hospital.vda5050.HospitalAgvMain}, {@code ./triad robot}); {@link
 * org.triad.examples.hospital.vda5050.VdaCourier} and {@link org.triad.examples.hospital.vda5050.VdaBuilding}
 * are the robotics expert's implementation of the generated {@code IRobot}/{@code IWorld} on master control's
 * {@link org.triad.vda5050.master.RemoteAgv}, beside the in-process simulated one.
 */
package org.triad.examples.hospital.vda5050;
