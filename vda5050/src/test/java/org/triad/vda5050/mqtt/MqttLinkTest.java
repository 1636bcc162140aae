package org.triad.vda5050.mqtt;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import com.fasterxml.jackson.databind.node.ObjectNode;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.triad.vda5050.broker.MosquittoBroker;
import org.triad.vda5050.protocol.Connection;
import org.triad.vda5050.protocol.Header;
import org.triad.vda5050.protocol.HeaderIds;
import org.triad.vda5050.protocol.Messages.ConnectionState;
import org.triad.vda5050.protocol.Topic;
import org.triad.vda5050.protocol.VdaJson;

/** The MQTT link on a real Mosquitto: delivery, validation both ways, last will, and a broker that is not there. */
class MqttLinkTest {
    private static MosquittoBroker broker;

    @BeforeAll
    static void start() {
        broker = MosquittoBroker.start(Path.of("target", "mosquitto", "MqttLinkTest"));
    }

    @AfterAll
    static void stop() {
        broker.close();
    }

    private static Connection connection(String serial, ConnectionState s) {
        return new Connection(0, HeaderIds.now(), Header.VERSION, "triad", serial, s);
    }

    private static void await(java.util.function.BooleanSupplier c) throws InterruptedException {
        for (int i = 0; i < 200 && !c.getAsBoolean(); i++) {
            Thread.sleep(25);
        }
    }

    @Test
    void validMessagesArriveMalformedOnesAreReportedWithTheirTopic() throws Exception {
        List<Received> got = new CopyOnWriteArrayList<>();
        List<String> problems = new CopyOnWriteArrayList<>();
        try (MqttLink rx = MqttLink.connect(broker.url(), "rx-1", null, problems::add, 10, 5);
                MqttLink tx = MqttLink.connect(broker.url(), "tx-1", null, line -> { }, 10, 5)) {
            rx.subscribe(Topic.CONNECTION.of("triad", "r1"), got::add);
            String topic = Topic.CONNECTION.of("triad", "r1");
            tx.publishRaw(topic, "nope".getBytes(StandardCharsets.UTF_8), false);
            ObjectNode wrong = (ObjectNode) VdaJson.tree(connection("r1", ConnectionState.ONLINE));
            wrong.remove("timestamp");
            tx.publishRaw(topic, VdaJson.write(wrong), false);
            tx.publish(topic, connection("r1", ConnectionState.ONLINE), false);
            await(() -> got.size() == 1 && problems.size() == 2);
            assertEquals(ConnectionState.ONLINE, got.get(0).as(Connection.class).connectionState());
            assertEquals(2, problems.size(), problems.toString());
            assertTrue(problems.get(0).startsWith("vda5050: ignored message on uagv/v2/triad/r1/connection: not valid JSON"), problems.get(0));
            assertTrue(problems.get(1).startsWith("vda5050: ignored message on uagv/v2/triad/r1/connection: violates the connection schema"),
                    problems.get(1));
            assertEquals(2, rx.rejectedCount());
        }
    }

    @Test
    void aMalformedMessageOfOursIsRefusedBeforeSending() {
        try (MqttLink tx = MqttLink.connect(broker.url(), "tx-2", null, line -> { }, 10, 5)) {
            IllegalStateException e = assertThrows(IllegalStateException.class,
                    () -> tx.publish(Topic.CONNECTION.of("triad", "r2"), new Connection(0, "now", null, "triad", "r2", null), false));
            assertTrue(e.getMessage().startsWith("refusing to send a malformed message on uagv/v2/triad/r2/connection"), e.getMessage());
        }
    }

    @Test
    void theLastWillIsPublishedWhenTheConnectionDies() throws Exception {
        List<Received> got = new CopyOnWriteArrayList<>();
        String topic = Topic.CONNECTION.of("triad", "r3");
        try (MqttLink rx = MqttLink.connect(broker.url(), "rx-3", null, line -> { }, 10, 5)) {
            rx.subscribe(topic, got::add);
            MqttLink dying = MqttLink.connect(broker.url(), "r3", new MqttLink.Will(topic, connection("r3", ConnectionState.CONNECTIONBROKEN)),
                    line -> { }, 10, 5);
            // a restart of the broker drops every connection without a DISCONNECT: the broker sends the will
            broker.restart();
            await(() -> got.stream().anyMatch(r -> r.as(Connection.class).connectionState() == ConnectionState.CONNECTIONBROKEN));
            assertTrue(got.stream().anyMatch(r -> r.as(Connection.class).connectionState() == ConnectionState.CONNECTIONBROKEN), got.toString());
            dying.close();
        }
    }

    @Test
    void noBrokerIsOneLineNamingHostAndPort() {
        int port = MosquittoBroker.freePort();
        BrokerUnreachableException e = assertThrows(BrokerUnreachableException.class,
                () -> MqttLink.connect("tcp://127.0.0.1:" + port, "nobody", null, line -> { }, 10, 2));
        assertTrue(e.getMessage().startsWith("no MQTT broker at 127.0.0.1:" + port + " "), e.getMessage());
        assertFalse(e.getMessage().contains("\n"));
        IllegalArgumentException bad = assertThrows(IllegalArgumentException.class,
                () -> MqttLink.connect("localhost:1883", "nobody", null, line -> { }, 10, 2));
        assertEquals("not a broker address: 'localhost:1883' (expected ssl://HOST:PORT or tcp://HOST:PORT)", bad.getMessage());
    }

    @Test
    void topicFiltersMatchLikeMqtt() {
        assertTrue(MqttLink.matches("uagv/v2/+/+/state", "uagv/v2/triad/c1/state"));
        assertFalse(MqttLink.matches("uagv/v2/+/+/state", "uagv/v2/triad/c1/order"));
        assertTrue(MqttLink.matches("uagv/#", "uagv/v2/triad/c1/order"));
        assertFalse(MqttLink.matches("uagv/v2/+/state", "uagv/v2/triad/c1/state"));
    }
}
