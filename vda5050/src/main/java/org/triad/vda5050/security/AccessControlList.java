package org.triad.vda5050.security;

import java.util.List;

import org.triad.vda5050.protocol.Topic;

/**
 * Mosquitto's access control list for VDA 5050: master control sends orders and instant actions to every
 * AGV and reads what every AGV reports; each robot publishes only its own connection, state,
 * visualization and factsheet and reads only its own order and instant actions. The building's devices
 * (doors, lifts; {@code org.triad.vda5050.devices}) are served by the identity {@value BrokerCredentials#BUILDING}
 * alone: only it reads the requests and only it publishes the devices' states, while master control and
 * the robots may ask (publish requests) and watch (read states) but neither answer for a device nor read
 * what others asked. Everything not granted is denied (Mosquitto drops a denied publication and never
 * delivers a denied topic).
 */
final class AccessControlList {
    /** Every device's requests: {@code triad/devices/v1/<doors|lifts>/<name>/request} (see DeviceMessages). */
    static final String DEVICE_REQUESTS = "triad/devices/v1/+/+/request";
    /** Every device's state: {@code triad/devices/v1/<doors|lifts>/<name>/state}. */
    static final String DEVICE_STATES = "triad/devices/v1/+/+/state";

    private AccessControlList() {
    }

    static String of(String manufacturer, List<String> robots) {
        StringBuilder acl = new StringBuilder("# written by ./triad broker from the identities in clients/; edits are overwritten\n\n");
        acl.append("user ").append(BrokerCredentials.MASTER).append('\n');
        for (Topic t : List.of(Topic.ORDER, Topic.INSTANT_ACTIONS)) {
            acl.append("topic write ").append(t.ofAll()).append('\n');
        }
        for (Topic t : List.of(Topic.CONNECTION, Topic.STATE, Topic.VISUALIZATION, Topic.FACTSHEET)) {
            acl.append("topic read ").append(t.ofAll()).append('\n');
        }
        asksDevices(acl);
        acl.append("\nuser ").append(BrokerCredentials.BUILDING).append('\n');
        acl.append("topic read ").append(DEVICE_REQUESTS).append('\n');
        acl.append("topic write ").append(DEVICE_STATES).append('\n');
        for (String serial : robots) {
            acl.append("\nuser ").append(serial).append('\n');
            for (Topic t : List.of(Topic.CONNECTION, Topic.STATE, Topic.VISUALIZATION, Topic.FACTSHEET)) {
                acl.append("topic write ").append(t.of(manufacturer, serial)).append('\n');
            }
            for (Topic t : List.of(Topic.ORDER, Topic.INSTANT_ACTIONS)) {
                acl.append("topic read ").append(t.of(manufacturer, serial)).append('\n');
            }
            asksDevices(acl);
        }
        return acl.toString();
    }

    /** A device's client: may request any door or lift and read every device's state. */
    private static void asksDevices(StringBuilder acl) {
        acl.append("topic write ").append(DEVICE_REQUESTS).append('\n');
        acl.append("topic read ").append(DEVICE_STATES).append('\n');
    }
}
