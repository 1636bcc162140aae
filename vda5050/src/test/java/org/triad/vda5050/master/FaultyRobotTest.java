package org.triad.vda5050.master;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BiConsumer;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.triad.vda5050.broker.MosquittoBroker;
import org.triad.vda5050.mqtt.MqttLink;
import org.triad.vda5050.protocol.AgvState;
import org.triad.vda5050.protocol.Connection;
import org.triad.vda5050.protocol.Header;
import org.triad.vda5050.protocol.HeaderIds;
import org.triad.vda5050.protocol.Messages;
import org.triad.vda5050.protocol.Messages.ConnectionState;
import org.triad.vda5050.protocol.Order;
import org.triad.vda5050.protocol.Topic;

/**
 * Master control against a robot that is authenticated but faulty (or lying): a headerId jump, a state for
 * an order master control never sent, a payload naming another serial number. Each is logged and handled,
 * and the order of master control still completes. A plain broker suffices: the robot has the right to
 * publish on its own topics either way.
 */
class FaultyRobotTest {
    private static final String M = MasterControl.TRIAD;
    private static MosquittoBroker broker;

    @BeforeAll
    static void start() {
        broker = MosquittoBroker.start(Path.of("target", "mosquitto", "FaultyRobotTest"));
    }

    @AfterAll
    static void stop() {
        broker.close();
    }

    private static final List<FakeAgv> FAKES = new CopyOnWriteArrayList<>();

    @AfterEach
    void closeFakes() {
        FAKES.forEach(FakeAgv::close);
        FAKES.clear();
    }

    /** A fake AGV: announces itself, then answers every order with what {@code answer} publishes. */
    private record FakeAgv(MqttLink link, String serial, AtomicInteger headerIds) implements AutoCloseable {
        static FakeAgv start(String serial, BiConsumer<FakeAgv, Order> answer) {
            MqttLink link = MqttLink.connect(broker.url(), "fake-" + serial, null, line -> { }, 5, 5);
            FakeAgv agv = new FakeAgv(link, serial, new AtomicInteger());
            FAKES.add(agv);
            link.subscribe(Topic.ORDER.of(M, serial), r -> answer.accept(agv, r.as(Order.class)));
            link.publish(Topic.CONNECTION.of(M, serial), new Connection(0, HeaderIds.now(), Header.VERSION, M, serial, ConnectionState.ONLINE), true);
            agv.state(agv.headerIds.incrementAndGet(), "", false);
            return agv;
        }

        void state(int headerId, String orderId, boolean driving) {
            stateNaming(serial, headerId, orderId, driving);
        }

        void stateNaming(String namedSerial, int headerId, String orderId, boolean driving) {
            link.publish(Topic.STATE.of(M, serial), new AgvState(headerId, HeaderIds.now(), Header.VERSION, M, namedSerial, orderId, 0, null, "a", 0,
                    List.of(), List.of(), null, null, null, driving, null, null, null, List.of(), new Messages.BatteryState(80, false), "AUTOMATIC",
                    List.of(), null, new Messages.SafetyState("NONE", false)), false);
        }

        @Override
        public void close() {
            link.close();
        }
    }

    private static MqttLink link(String broker, String clientId) {
        return MqttLink.connect(broker, clientId, null, line -> { }, 5, 5);
    }

    private static VdaTimeouts quick() {
        return new VdaTimeouts(10, 5, 20, 3);
    }

    @Test
    void aHeaderIdJumpDoesNotBlindMasterControl() {
        List<String> log = new CopyOnWriteArrayList<>();
        AtomicInteger orders = new AtomicInteger();
        try (MasterControl master = MasterControl.connect(broker.url(), quick(), log::add)) {
            RemoteAgv remote = master.agv("jumper");
            FakeAgv.start("jumper", (a, o) -> {
                if (orders.incrementAndGet() == 1) {
                    // the first answer: one state with the largest headerId, then states counting on from where they were
                    a.state(Integer.MAX_VALUE, o.orderId(), true);
                }
                a.state(a.headerIds().incrementAndGet(), o.orderId(), true);
                a.state(a.headerIds().incrementAndGet(), o.orderId(), false);
            });
            assertTrue(remote.drive("a", "b"), remote.lastFailure().orElse(""));
            // the next order too: every later state of the AGV is still believed
            assertTrue(remote.drive("b", "a"), remote.lastFailure().orElse(""));
            assertTrue(log.stream().anyMatch(l -> l.contains("jumped from state headerId")), log.toString());
            assertTrue(log.stream().anyMatch(l -> l.contains("went back from state headerId 2147483647 to")), log.toString());
        }
    }

    @Test
    void aStateForAnOrderNeverSentIsLoggedAndNotTakenAsProgress() {
        List<String> log = new CopyOnWriteArrayList<>();
        try (MasterControl master = MasterControl.connect(broker.url(), quick(), log::add)) {
            RemoteAgv remote = master.agv("stranger");
            FakeAgv.start("stranger", (a, o) -> {
                // claims an order nobody sent, finished, before it reports ours
                a.state(a.headerIds().incrementAndGet(), "someone-elses-order", false);
                a.state(a.headerIds().incrementAndGet(), o.orderId(), true);
                sleep(200);
                a.state(a.headerIds().incrementAndGet(), o.orderId(), false);
            });
            assertTrue(remote.drive("a", "b"), remote.lastFailure().orElse(""));
            assertEquals(1, log.stream().filter(l -> l.contains("reports order 'someone-elses-order', which this master control never sent")).count(),
                    log.toString());
        }
    }

    @Test
    void aPayloadNamingAnotherSerialIsRefused() {
        List<String> log = new CopyOnWriteArrayList<>();
        List<AgvState> seen = new CopyOnWriteArrayList<>();
        try (MasterControl master = MasterControl.connect(broker.url(), quick(), log::add)) {
            master.link().subscribe(Topic.STATE.of(M, "liar"), r -> seen.add(r.as(AgvState.class)));
            RemoteAgv remote = master.agv("liar");
            FakeAgv.start("liar", (a, o) -> {
                // a finished state for our order, but naming another AGV: refused; the real ones follow
                a.stateNaming("courier-9", a.headerIds().incrementAndGet(), o.orderId(), false);
                a.state(a.headerIds().incrementAndGet(), o.orderId(), true);
                sleep(300);
                a.state(a.headerIds().incrementAndGet(), o.orderId(), false);
            });
            assertTrue(remote.drive("a", "b"), remote.lastFailure().orElse(""));
            assertTrue(log.stream().anyMatch(l -> l.equals("vda5050: ignored message on uagv/v2/triad/liar/state: its serialNumber 'courier-9'"
                    + " is not the topic's 'liar'")), log.toString());
            assertTrue(seen.stream().noneMatch(s -> s.serialNumber().equals("courier-9")), seen.toString());
        }
        // and a robot refuses an order naming another serial number the same way (one MqttLink for both sides)
        List<String> robotLog = new CopyOnWriteArrayList<>();
        List<Order> got = new CopyOnWriteArrayList<>();
        try (MqttLink robot = MqttLink.connect(broker.url(), "robot-x", null, robotLog::add, 5, 5); MqttLink master = link(broker.url(), "master-x")) {
            robot.subscribe(Topic.ORDER.of(M, "courier-x"), r -> got.add(r.as(Order.class)));
            master.publish(Topic.ORDER.of(M, "courier-x"), new Order(1, HeaderIds.now(), Header.VERSION, M, "courier-y", "o1", 0, null,
                    List.of(new Messages.Node("a", 0, null, true, null, List.of())), List.of()), false);
            master.publish(Topic.ORDER.of(M, "courier-x"), new Order(2, HeaderIds.now(), Header.VERSION, M, "courier-x", "o2", 0, null,
                    List.of(new Messages.Node("a", 0, null, true, null, List.of())), List.of()), false);
            for (int i = 0; i < 400 && got.isEmpty(); i++) {
                sleep(25);
            }
            assertEquals(List.of("o2"), got.stream().map(Order::orderId).toList());
            assertEquals(List.of("vda5050: ignored message on uagv/v2/triad/courier-x/order: its serialNumber 'courier-y' is not the topic's 'courier-x'"),
                    robotLog);
        }
    }

    private static void sleep(long ms) {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
