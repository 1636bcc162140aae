package org.triad.vda5050.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Set;

import com.fasterxml.jackson.databind.node.ObjectNode;

import org.junit.jupiter.api.Test;
import org.triad.vda5050.protocol.Messages.Action;
import org.triad.vda5050.protocol.Messages.ActionParameter;
import org.triad.vda5050.protocol.Messages.ActionState;
import org.triad.vda5050.protocol.Messages.ActionStatus;
import org.triad.vda5050.protocol.Messages.AgvError;
import org.triad.vda5050.protocol.Messages.AgvPosition;
import org.triad.vda5050.protocol.Messages.BatteryState;
import org.triad.vda5050.protocol.Messages.BlockingType;
import org.triad.vda5050.protocol.Messages.ConnectionState;
import org.triad.vda5050.protocol.Messages.Edge;
import org.triad.vda5050.protocol.Messages.EdgeState;
import org.triad.vda5050.protocol.Messages.ErrorLevel;
import org.triad.vda5050.protocol.Messages.Load;
import org.triad.vda5050.protocol.Messages.Node;
import org.triad.vda5050.protocol.Messages.NodeState;
import org.triad.vda5050.protocol.Messages.Reference;
import org.triad.vda5050.protocol.Messages.SafetyState;

/** Triad's message records against the official schemas, and the schemas catching what is wrong. */
class MessageSchemasTest {
    private final MessageSchemas schemas = MessageSchemas.get();

    static Order order() {
        Action pick = new Action("pick", "a1", null, BlockingType.HARD, List.of(new ActionParameter("loadId", "gauze")));
        return new Order(3, HeaderIds.now(), Header.VERSION, "triad", "courier-1", "o1", 0, null,
                List.of(new Node("c1", 0, null, true, null, List.of()), new Node("storage", 2, null, true, null, List.of(pick))),
                List.of(new Edge("c1-storage", 1, null, true, "c1", "storage", List.of())));
    }

    static AgvState state() {
        return new AgvState(7, HeaderIds.now(), Header.VERSION, "triad", "courier-1", "o1", 0, null, "c1", 0,
                List.of(new NodeState("storage", 2, null, null, true)), List.of(new EdgeState("c1-storage", 1, null, true)),
                new AgvPosition(4, 14.2, 0.5, "hospital", true), null, List.of(new Load("gauze", "item", null)), true, false, null, null,
                List.of(new ActionState("a1", "pick", null, ActionStatus.WAITING, null)), new BatteryState(100, false), "AUTOMATIC",
                List.of(new AgvError("DOOR_CLOSED", List.of(new Reference("orderId", "o1")), "door 'fireDoor' stayed closed", ErrorLevel.WARNING)),
                null, new SafetyState("NONE", false));
    }

    @Test
    void triadsMessagesConformToTheOfficialSchemas() {
        assertEquals(Set.of(), schemas.violations(Topic.ORDER, VdaJson.tree(order())));
        assertEquals(Set.of(), schemas.violations(Topic.STATE, VdaJson.tree(state())));
        assertEquals(Set.of(), schemas.violations(Topic.CONNECTION,
                VdaJson.tree(new Connection(0, HeaderIds.now(), Header.VERSION, "triad", "courier-1", ConnectionState.CONNECTIONBROKEN))));
        assertEquals(Set.of(), schemas.violations(Topic.INSTANT_ACTIONS, VdaJson.tree(new InstantActions(0, HeaderIds.now(), Header.VERSION,
                "triad", "courier-1", List.of(new Action("cancelOrder", "c1", null, BlockingType.HARD, null))))));
    }

    @Test
    void messagesRoundTripThroughJson() {
        AgvState s = state();
        AgvState back = VdaJson.bind(VdaJson.parse(VdaJson.write(s)), AgvState.class);
        assertEquals(s, back);
        assertTrue(back.carries("gauze"));
        assertEquals("DOOR_CLOSED: door 'fireDoor' stayed closed", back.errors().get(0).describe());
        assertEquals("o1", back.errors().get(0).reference("orderId"));
    }

    @Test
    void aMissingRequiredFieldOrAWrongEnumValueIsAViolation() {
        ObjectNode o = (ObjectNode) VdaJson.tree(order());
        o.remove("orderUpdateId");
        VdaMessageException e = assertThrows(VdaMessageException.class, () -> schemas.check(Topic.ORDER, o));
        assertTrue(e.getMessage().startsWith("violates the order schema: ") && e.getMessage().contains("orderUpdateId"), e.getMessage());
        ObjectNode c = (ObjectNode) VdaJson.tree(new Connection(0, HeaderIds.now(), Header.VERSION, "triad", "courier-1", ConnectionState.ONLINE));
        c.put("connectionState", "ASLEEP");
        assertFalse(schemas.violations(Topic.CONNECTION, c).isEmpty());
    }

    @Test
    void notJsonIsOneLine() {
        VdaMessageException e = assertThrows(VdaMessageException.class, () -> VdaJson.parse("{\"a\":\n".getBytes(StandardCharsets.UTF_8)));
        assertTrue(e.getMessage().startsWith("not valid JSON: "), e.getMessage());
        assertFalse(e.getMessage().contains("\n"));
    }

    @Test
    void topicsFollowTheInterfaceNaming() {
        assertEquals("uagv/v2/triad/courier-1/instantActions", Topic.INSTANT_ACTIONS.of("triad", "courier-1"));
        assertEquals("uagv/v2/+/+/state", Topic.STATE.ofAll());
        Topic.Address a = Topic.parse("uagv/v3/acme/agv7/order").orElseThrow();
        assertEquals(new Topic.Address("v3", "acme", "agv7", Topic.ORDER), a);
        assertTrue(Topic.parse("uagv/v2/acme/agv7/unknown").isEmpty());
        assertThrows(IllegalArgumentException.class, () -> Topic.STATE.of("triad", "a/b"));
        assertEquals(2, Header.majorOf("2.1.0"));
        assertEquals(-1, Header.majorOf("two"));
    }
}
