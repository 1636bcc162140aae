package org.triad.vda5050.protocol;

import java.util.List;

import com.fasterxml.jackson.annotation.JsonInclude;

import org.triad.vda5050.protocol.Messages.Action;

/** Actions an AGV executes at once, outside its order (cancelOrder, startPause, factsheetRequest, ...). */
@JsonInclude(JsonInclude.Include.NON_NULL)
public record InstantActions(int headerId, String timestamp, String version, String manufacturer, String serialNumber,
        List<Action> actions) implements Header {
    public InstantActions {
        actions = List.copyOf(actions);
    }
}
