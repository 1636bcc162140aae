package org.triad.vda5050.protocol;

import java.util.List;
import java.util.Optional;

import com.fasterxml.jackson.annotation.JsonInclude;

import org.triad.vda5050.protocol.Messages.ActionState;
import org.triad.vda5050.protocol.Messages.AgvPosition;
import org.triad.vda5050.protocol.Messages.BatteryState;
import org.triad.vda5050.protocol.Messages.EdgeState;
import org.triad.vda5050.protocol.Messages.AgvError;
import org.triad.vda5050.protocol.Messages.Information;
import org.triad.vda5050.protocol.Messages.Load;
import org.triad.vda5050.protocol.Messages.NodeState;
import org.triad.vda5050.protocol.Messages.SafetyState;
import org.triad.vda5050.protocol.Messages.Velocity;

/** The state topic's message: everything an AGV reports about itself and its order. */
@JsonInclude(JsonInclude.Include.NON_NULL)
public record AgvState(int headerId, String timestamp, String version, String manufacturer, String serialNumber, String orderId,
        int orderUpdateId, String zoneSetId, String lastNodeId, int lastNodeSequenceId, List<NodeState> nodeStates,
        List<EdgeState> edgeStates, AgvPosition agvPosition, Velocity velocity, List<Load> loads, boolean driving, Boolean paused,
        Boolean newBaseRequest, Double distanceSinceLastNode, List<ActionState> actionStates, BatteryState batteryState,
        String operatingMode, List<AgvError> errors, List<Information> information, SafetyState safetyState) implements Header {
    public AgvState {
        nodeStates = List.copyOf(nodeStates);
        edgeStates = List.copyOf(edgeStates);
        loads = loads == null ? null : List.copyOf(loads);
        actionStates = List.copyOf(actionStates);
        errors = List.copyOf(errors);
        information = information == null ? null : List.copyOf(information);
    }

    /** The state of the action with this id, if the AGV reports it. */
    public Optional<ActionState> actionState(String actionId) {
        return actionStates.stream().filter(a -> a.actionId().equals(actionId)).findFirst();
    }

    /** Whether the AGV reports a load with this id. */
    public boolean carries(String loadId) {
        return loads != null && loads.stream().anyMatch(l -> loadId.equals(l.loadId()));
    }

    /** The information entries of this type (AGV-specific facts such as whom it follows). */
    public List<Information> information(String infoType) {
        return information == null ? List.of() : information.stream().filter(i -> i.infoType().equals(infoType)).toList();
    }
}
