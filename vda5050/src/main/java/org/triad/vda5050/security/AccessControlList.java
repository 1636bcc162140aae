package org.triad.vda5050.security;

import java.util.List;

import org.triad.vda5050.protocol.Topic;

/**
 * Mosquitto's access control list for VDA 5050: master control sends orders and instant actions to every
 * AGV and reads what every AGV reports; each robot publishes only its own connection, state,
 * visualization and factsheet and reads only its own order and instant actions. Everything not granted
 * is denied (Mosquitto drops a denied publication and never delivers a denied topic).
 */
final class AccessControlList {
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
        for (String serial : robots) {
            acl.append("\nuser ").append(serial).append('\n');
            for (Topic t : List.of(Topic.CONNECTION, Topic.STATE, Topic.VISUALIZATION, Topic.FACTSHEET)) {
                acl.append("topic write ").append(t.of(manufacturer, serial)).append('\n');
            }
            for (Topic t : List.of(Topic.ORDER, Topic.INSTANT_ACTIONS)) {
                acl.append("topic read ").append(t.of(manufacturer, serial)).append('\n');
            }
        }
        return acl.toString();
    }
}
