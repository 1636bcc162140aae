package org.triad.vda5050.protocol;

import com.fasterxml.jackson.annotation.JsonInclude;

import org.triad.vda5050.protocol.Messages.ConnectionState;

/** An AGV's connection to the broker: ONLINE, OFFLINE, or CONNECTIONBROKEN (its last will). */
@JsonInclude(JsonInclude.Include.NON_NULL)
public record Connection(int headerId, String timestamp, String version, String manufacturer, String serialNumber,
        ConnectionState connectionState) implements Header {
}
