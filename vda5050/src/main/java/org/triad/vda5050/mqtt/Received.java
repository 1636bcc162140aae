package org.triad.vda5050.mqtt;

import com.fasterxml.jackson.databind.JsonNode;

import org.triad.vda5050.protocol.Topic;
import org.triad.vda5050.protocol.VdaJson;

/** A message that arrived, was valid JSON, conformed to its topic's schema and speaks our major version. */
public record Received(String mqttTopic, Topic.Address address, JsonNode json) {
    public <T> T as(Class<T> type) {
        return VdaJson.bind(json, type);
    }
}
