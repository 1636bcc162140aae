package org.triad.vda5050.protocol;

import java.util.List;

import com.fasterxml.jackson.annotation.JsonInclude;

/**
 * The parts of VDA 5050 messages, as records named and shaped like the official schemas (optional
 * fields are {@code null} and left out of the JSON).
 */
public final class Messages {
    private Messages() {
    }

    public enum BlockingType { NONE, SOFT, HARD }

    public enum ActionStatus { WAITING, INITIALIZING, RUNNING, FINISHED, FAILED }

    public enum ConnectionState { ONLINE, OFFLINE, CONNECTIONBROKEN }

    public enum ErrorLevel { WARNING, FATAL }

    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record ActionParameter(String key, Object value) {
    }

    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record Action(String actionType, String actionId, String actionDescription, BlockingType blockingType,
            List<ActionParameter> actionParameters) {
        public Action {
            actionParameters = actionParameters == null ? null : List.copyOf(actionParameters);
        }

        /** The value of a parameter, or null. */
        public Object parameter(String key) {
            if (actionParameters == null) {
                return null;
            }
            return actionParameters.stream().filter(p -> p.key().equals(key)).map(ActionParameter::value).findFirst().orElse(null);
        }
    }

    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record NodePosition(double x, double y, Double theta, String mapId) {
    }

    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record Node(String nodeId, int sequenceId, String nodeDescription, boolean released, NodePosition nodePosition,
            List<Action> actions) {
        public Node {
            actions = List.copyOf(actions);
        }
    }

    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record Edge(String edgeId, int sequenceId, String edgeDescription, boolean released, String startNodeId,
            String endNodeId, List<Action> actions) {
        public Edge {
            actions = List.copyOf(actions);
        }
    }

    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record NodeState(String nodeId, int sequenceId, String nodeDescription, NodePosition nodePosition, boolean released) {
    }

    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record EdgeState(String edgeId, int sequenceId, String edgeDescription, boolean released) {
    }

    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record AgvPosition(double x, double y, double theta, String mapId, boolean positionInitialized) {
    }

    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record Velocity(Double vx, Double vy, Double omega) {
    }

    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record Load(String loadId, String loadType, String loadPosition) {
    }

    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record ActionState(String actionId, String actionType, String actionDescription, ActionStatus actionStatus,
            String resultDescription) {
    }

    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record BatteryState(double batteryCharge, boolean charging) {
    }

    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record Reference(String referenceKey, String referenceValue) {
    }

    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record AgvError(String errorType, List<Reference> errorReferences, String errorDescription, ErrorLevel errorLevel) {
        public AgvError {
            errorReferences = errorReferences == null ? null : List.copyOf(errorReferences);
        }

        /** The value of a reference, or null. */
        public String reference(String key) {
            if (errorReferences == null) {
                return null;
            }
            return errorReferences.stream().filter(r -> r.referenceKey().equals(key)).map(Reference::referenceValue).findFirst()
                    .orElse(null);
        }

        /** {@code doorClosed: door 'fire' on edge c2-c3 stayed closed}, for Status. */
        public String describe() {
            return errorType + (errorDescription == null ? "" : ": " + errorDescription);
        }
    }

    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record Information(String infoType, List<Reference> infoReferences, String infoDescription, String infoLevel) {
    }

    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record SafetyState(String eStop, boolean fieldViolation) {
    }
}
