package org.triad.vda5050.master;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInfo;
import org.triad.vda5050.broker.MosquittoBroker;
import org.triad.vda5050.mqtt.MqttLink;
import org.triad.vda5050.protocol.AgvState;
import org.triad.vda5050.protocol.Connection;
import org.triad.vda5050.protocol.Header;
import org.triad.vda5050.protocol.HeaderIds;
import org.triad.vda5050.protocol.Messages.BatteryState;
import org.triad.vda5050.protocol.Messages.ConnectionState;
import org.triad.vda5050.protocol.Messages.SafetyState;
import org.triad.vda5050.protocol.Topic;

/**
 * What master control believes about an AGV's connection, on a real Mosquitto: a last will that arrives
 * while the AGV keeps reporting state (what a broker restart produces: the stopping broker publishes the
 * will of every connected client and keeps it retained) does not make the AGV count as down; a will
 * after which nothing more comes does.
 */
class RemoteAgvLivenessTest {
    private static final VdaTimeouts TIMEOUTS = new VdaTimeouts(30, 10, 30, 5); // generous: a loaded machine delays states
    private MosquittoBroker broker;

    @BeforeEach
    void start(TestInfo test) {
        broker = MosquittoBroker.start(Path.of("target", "mosquitto", "RemoteAgvLivenessTest-" + test.getTestMethod().orElseThrow().getName()));
    }

    @AfterEach
    void stop() {
        broker.close();
    }

    private static AgvState state(int headerId, String serial) {
        return new AgvState(headerId, HeaderIds.now(), Header.VERSION, MasterControl.TRIAD, serial, "", 0, null, "lobby", 0, List.of(), List.of(),
                null, null, List.of(), false, false, null, null, List.of(), new BatteryState(100, false), "AUTOMATIC", List.of(), null,
                new SafetyState("NONE", false));
    }

    private static Connection connection(int headerId, String serial, ConnectionState s) {
        return new Connection(headerId, HeaderIds.now(), Header.VERSION, MasterControl.TRIAD, serial, s);
    }

    /** An AGV that announces itself and then reports state every 200 ms until stopped. */
    private static Thread reporting(MqttLink agv, String serial, AtomicBoolean running) {
        agv.publish(Topic.CONNECTION.of(MasterControl.TRIAD, serial), connection(0, serial, ConnectionState.ONLINE), true);
        AtomicInteger ids = new AtomicInteger();
        Thread t = new Thread(() -> {
            while (running.get()) {
                agv.publish(Topic.STATE.of(MasterControl.TRIAD, serial), state(ids.getAndIncrement(), serial), false);
                try {
                    Thread.sleep(200);
                } catch (InterruptedException e) {
                    return;
                }
            }
        });
        t.setDaemon(true);
        t.start();
        return t;
    }

    private static void awaitConnection(RemoteAgv agv, ConnectionState s) throws InterruptedException {
        long deadline = System.nanoTime() + 10_000_000_000L;
        while (agv.connection().orElseThrow() != s && System.nanoTime() < deadline) {
            Thread.sleep(10);
        }
        assertTrue(agv.connection().orElseThrow() == s, "master control received " + s);
    }

    @Test
    void aLastWillFollowedByStatesLeavesTheAgvOnline() throws Exception {
        AtomicBoolean running = new AtomicBoolean(true);
        try (MasterControl master = MasterControl.connect(broker.url(), TIMEOUTS, line -> { });
                MqttLink agv = MqttLink.connect(broker.url(), "agv-a1", null, line -> { }, 10, 5);
                MqttLink stoppingBroker = MqttLink.connect(broker.url(), "stale-will", null, line -> { }, 10, 5)) {
            RemoteAgv a1 = master.agv("a1");
            Thread reporter = reporting(agv, "a1", running);
            assertTrue(a1.awaitOnline(), "online after ONLINE and a state");
            // the will as a stopping broker publishes it after the AGV's ONLINE: outdated headerId 0, retained
            stoppingBroker.publish(Topic.CONNECTION.of(MasterControl.TRIAD, "a1"), connection(0, "a1", ConnectionState.CONNECTIONBROKEN), true);
            awaitConnection(a1, ConnectionState.CONNECTIONBROKEN);
            assertTrue(a1.awaitOnline(), "the states that follow the will show the AGV connected");
            assertTrue(a1.isOnline());
            running.set(false);
            reporter.join(2000);
        }
    }

    @Test
    void aLastWillAfterWhichNothingComesIsDown() throws Exception {
        AtomicBoolean running = new AtomicBoolean(true);
        try (MasterControl master = MasterControl.connect(broker.url(), TIMEOUTS, line -> { });
                MqttLink agv = MqttLink.connect(broker.url(), "agv-a2", null, line -> { }, 10, 5);
                MqttLink theBroker = MqttLink.connect(broker.url(), "real-will", null, line -> { }, 10, 5)) {
            RemoteAgv a2 = master.agv("a2");
            Thread reporter = reporting(agv, "a2", running);
            assertTrue(a2.awaitOnline());
            running.set(false);
            reporter.join(2000);
            Thread.sleep(500); // the last state reaches master control before the will, which comes over another connection
            theBroker.publish(Topic.CONNECTION.of(MasterControl.TRIAD, "a2"), connection(0, "a2", ConnectionState.CONNECTIONBROKEN), true);
            awaitConnection(a2, ConnectionState.CONNECTIONBROKEN);
            assertFalse(a2.awaitOnline(), "down: the will is the last word from the AGV");
            assertFalse(a2.isOnline());
            assertFalse(a2.drive("lobby", "c4"));
            assertTrue(a2.lastFailure().orElseThrow().contains("is CONNECTIONBROKEN, cannot drive lobby -> c4"), a2.lastFailure().orElseThrow());
        }
    }
}
