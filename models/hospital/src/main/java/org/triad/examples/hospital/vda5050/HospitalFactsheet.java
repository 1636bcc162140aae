package org.triad.examples.hospital.vda5050;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.triad.sim.RobotSpec;
import org.triad.vda5050.master.MasterControl;
import org.triad.vda5050.protocol.Header;
import org.triad.vda5050.protocol.HeaderIds;
import org.triad.vda5050.protocol.VdaJson;

/** The factsheet of the simulated courier: what it is and which actions it takes, with their parameters. */
final class HospitalFactsheet {
    private HospitalFactsheet() {
    }

    static ObjectNode of(String serial, int headerId) {
        RobotSpec spec = org.triad.examples.hospital.HospitalObjects.courierSpec();
        ObjectNode f = VdaJson.mapper().createObjectNode();
        f.put("headerId", headerId).put("timestamp", HeaderIds.now()).put("version", Header.VERSION)
                .put("manufacturer", MasterControl.TRIAD).put("serialNumber", serial);
        ObjectNode type = f.putObject("typeSpecification");
        type.put("seriesName", "Triad simulated courier").put("seriesDescription", "a courier of the dyn4j hospital simulation")
                .put("agvKinematic", "DIFF").put("agvClass", "CARRIER").put("maxLoadMass", org.triad.examples.hospital.HospitalObjects.PAYLOAD_KG);
        type.putArray("localizationTypes").add("NATURAL");
        type.putArray("navigationTypes").add("AUTONOMOUS");
        f.putObject("physicalParameters").put("speedMin", 0).put("speedMax", spec.maxSpeed()).put("accelerationMax", spec.maxAcceleration())
                .put("decelerationMax", spec.maxAcceleration()).put("heightMax", 1.2).put("width", 2 * spec.radius())
                .put("length", 2 * spec.radius());
        ObjectNode limits = f.putObject("protocolLimits");
        limits.putObject("maxStringLens");
        limits.putObject("maxArrayLens");
        limits.putObject("timing").put("minOrderInterval", 0.1).put("minStateInterval", 0.1).put("defaultStateInterval", 1.0);
        ObjectNode features = f.putObject("protocolFeatures");
        features.putArray("optionalParameters");
        ArrayNode actions = features.putArray("agvActions");
        action(actions, "pick", "takes the item (load) at the node", "NODE").addObject().put("key", "loadId").put("valueDataType", "STRING");
        action(actions, "drop", "puts the item (load) down at the node", "NODE").addObject().put("key", "loadId").put("valueDataType", "STRING");
        action(actions, "startFollowing", "starts following the person standing at the node", "NODE").addObject().put("key", "personId")
                .put("valueDataType", "STRING");
        action(actions, "guide", "leads the person along the edge", "EDGE").addObject().put("key", "personId").put("valueDataType", "STRING");
        action(actions, "walk", "follows the person walking along the edge", "EDGE").addObject().put("key", "personId")
                .put("valueDataType", "STRING");
        action(actions, "passDoor", "passes the building's door on the edge (this simulated building opens it)", "EDGE").addObject()
                .put("key", "doorId").put("valueDataType", "STRING");
        action(actions, "ride", "rides the building's lift from landing to landing (this simulated building brings it)", "EDGE").addObject()
                .put("key", "liftId").put("valueDataType", "STRING");
        action(actions, "startCharging", "charges the battery full at the node's dock", "NODE");
        action(actions, "cancelOrder", "stops at the next node and drops the rest of the order", "INSTANT");
        action(actions, "startPause", "holds still", "INSTANT");
        action(actions, "stopPause", "goes on", "INSTANT");
        action(actions, "factsheetRequest", "publishes this factsheet", "INSTANT");
        action(actions, "stateRequest", "publishes a state", "INSTANT");
        f.putObject("agvGeometry");
        f.putObject("loadSpecification").putArray("loadPositions").add("tray");
        return f;
    }

    private static ArrayNode action(ArrayNode actions, String type, String description, String scope) {
        ObjectNode a = actions.addObject();
        a.put("actionType", type).put("actionDescription", description);
        a.putArray("actionScopes").add(scope);
        return a.putArray("actionParameters");
    }
}
