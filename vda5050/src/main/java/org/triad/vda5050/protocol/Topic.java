package org.triad.vda5050.protocol;

import java.util.Optional;

/** The VDA 5050 topics and their MQTT topic names {@code uagv/v2/{manufacturer}/{serialNumber}/{topic}}. */
public enum Topic {
    ORDER("order"), INSTANT_ACTIONS("instantActions"), STATE("state"), CONNECTION("connection"),
    VISUALIZATION("visualization"), FACTSHEET("factsheet");

    /** The interface name, first level of every topic. */
    public static final String INTERFACE = "uagv";

    private final String leaf;

    Topic(String leaf) {
        this.leaf = leaf;
    }

    /** The topic's last level and the name of its schema, e.g. {@code instantActions}. */
    public String leaf() {
        return leaf;
    }

    /** The topic of one AGV, e.g. {@code uagv/v2/triad/courier-1/state}. */
    public String of(String manufacturer, String serialNumber) {
        return INTERFACE + "/" + Header.MAJOR + "/" + level(manufacturer) + "/" + level(serialNumber) + "/" + leaf;
    }

    /** The topic filter for this topic of every AGV of every manufacturer. */
    public String ofAll() {
        return INTERFACE + "/" + Header.MAJOR + "/+/+/" + leaf;
    }

    /** The parts of an MQTT topic name of this interface, or empty if it is none. */
    public static Optional<Address> parse(String mqttTopic) {
        String[] p = mqttTopic.split("/", -1);
        if (p.length != 5 || !p[0].equals(INTERFACE)) {
            return Optional.empty();
        }
        for (Topic t : values()) {
            if (t.leaf.equals(p[4])) {
                return Optional.of(new Address(p[1], p[2], p[3], t));
            }
        }
        return Optional.empty();
    }

    /** Where a message was published: the major version in the topic, the AGV, and the topic. */
    public record Address(String major, String manufacturer, String serialNumber, Topic topic) {
    }

    private static String level(String s) {
        if (s == null || s.isEmpty() || s.contains("/") || s.contains("+") || s.contains("#")) {
            throw new IllegalArgumentException("not usable in an MQTT topic: '" + s + "'");
        }
        return s;
    }
}
