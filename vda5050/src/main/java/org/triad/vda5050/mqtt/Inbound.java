package org.triad.vda5050.mqtt;

import com.fasterxml.jackson.databind.JsonNode;

import org.triad.vda5050.protocol.Header;
import org.triad.vda5050.protocol.MessageSchemas;
import org.triad.vda5050.protocol.Topic;
import org.triad.vda5050.protocol.VdaJson;
import org.triad.vda5050.protocol.VdaMessageException;

/**
 * What every received message passes before a handler of master control or of a robot sees it: a topic of
 * this interface and major version, JSON, the same major version in the payload, the topic's official
 * schema, and a header naming the AGV of its topic. The one entry the fuzz tests drive.
 */
public final class Inbound {
    private Inbound() {
    }

    /**
     * The message as a handler gets it.
     *
     * @throws VdaMessageException naming what is wrong (the only exception for any topic and payload)
     */
    public static Received read(String mqttTopic, byte[] payload) {
        Topic.Address a = Topic.parse(mqttTopic).orElseThrow(() -> new VdaMessageException("not a VDA 5050 topic"));
        if (!a.major().equals(Header.MAJOR)) {
            throw new VdaMessageException("major version " + a.major() + " in the topic; Triad speaks " + Header.VERSION);
        }
        JsonNode json = VdaJson.parse(payload);
        JsonNode version = json.get("version");
        if (version != null && version.isTextual() && Header.majorOf(version.asText()) != Header.majorOf(Header.VERSION)) {
            throw new VdaMessageException("speaks VDA 5050 " + version.asText() + "; Triad speaks " + Header.VERSION);
        }
        MessageSchemas.get().check(a.topic(), json);
        checkSender(a, json);
        return new Received(mqttTopic, a, json);
    }

    /**
     * A message names its AGV twice, in the topic (what the broker's access control checked) and in its
     * header; one naming another AGV than its topic is refused (an order naming another serial number was
     * executed, a state could speak for another AGV).
     */
    private static void checkSender(Topic.Address a, JsonNode json) {
        for (String[] field : new String[][] { { "manufacturer", a.manufacturer() }, { "serialNumber", a.serialNumber() } }) {
            JsonNode v = json.get(field[0]);
            if (v != null && v.isTextual() && !v.asText().equals(field[1])) {
                throw new VdaMessageException("its " + field[0] + " '" + v.asText() + "' is not the topic's '" + field[1] + "'");
            }
        }
    }
}
