/**
 * One building, many robots: the building's map, the world state the fleet shares, who holds which
 * resource, and which task goes to which robot. Arrows point down only: the service and the robot
 * bindings use this package; it uses RefArc and knows nothing of MQTT, HTTP or dyn4j.
 */
package org.triad.building;
