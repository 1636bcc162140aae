package org.triad.fuzz;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;

import org.triad.vda5050.mqtt.Inbound;
import org.triad.vda5050.mqtt.Received;
import org.triad.vda5050.protocol.AgvState;
import org.triad.vda5050.protocol.Connection;
import org.triad.vda5050.protocol.InstantActions;
import org.triad.vda5050.protocol.Order;
import org.triad.vda5050.protocol.Topic;
import org.triad.vda5050.protocol.VdaMessageException;
import org.triad.vda5050.protocol.Visualization;

import com.code_intelligence.jazzer.junit.FuzzTest;

/**
 * The VDA 5050 messages master control (state, connection, factsheet, visualization) and a robot (order,
 * instantActions) receive, through the path every received message takes ({@link Inbound#read}) and the
 * record a handler reads it as: any payload is refused with one {@link VdaMessageException} line or read
 * as its record; nothing else escapes. The input's first byte picks the topic (its value modulo 6, in the
 * order order, instantActions, state, connection, visualization, factsheet), the rest is the payload; seeds
 * are valid messages and the payloads of issue 25 ({@code VdaMessagesFuzzTestInputs/received/}).
 */
class VdaMessagesFuzzTest {
	@FuzzTest(maxDuration = "10m")
	void received(byte[] input) {
		if (input.length == 0) {
			return;
		}
		Topic topic = Topic.values()[(input[0] & 0xff) % Topic.values().length];
		byte[] payload = Arrays.copyOfRange(input, 1, input.length);
		try {
			Received r = Inbound.read(topic.of("triad", "courier-1"), payload);
			switch (topic) {
				case ORDER -> r.as(Order.class);
				case INSTANT_ACTIONS -> r.as(InstantActions.class);
				case STATE -> r.as(AgvState.class);
				case CONNECTION -> r.as(Connection.class);
				case VISUALIZATION -> r.as(Visualization.class);
				case FACTSHEET -> assertTrue(r.json().isObject(), "a factsheet is an object");
			}
		} catch (VdaMessageException e) {
			String m = e.getMessage();
			assertTrue(m != null && !m.isBlank(), "a refusal says why");
			assertFalse(m.contains("\n"), "a refusal is one line: " + m);
		}
	}
}
