package org.triad.vda5050.protocol;

import com.fasterxml.jackson.annotation.JsonInclude;

import org.triad.vda5050.protocol.Messages.AgvPosition;
import org.triad.vda5050.protocol.Messages.Velocity;

/** The AGV's position at a higher rate than state, for visualization only. */
@JsonInclude(JsonInclude.Include.NON_NULL)
public record Visualization(int headerId, String timestamp, String version, String manufacturer, String serialNumber,
        AgvPosition agvPosition, Velocity velocity) implements Header {
}
