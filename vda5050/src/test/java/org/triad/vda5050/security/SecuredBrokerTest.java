package org.triad.vda5050.security;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.BooleanSupplier;

import javax.net.ssl.SSLContext;
import javax.net.ssl.SSLSocketFactory;

import org.eclipse.paho.client.mqttv3.MqttClient;
import org.eclipse.paho.client.mqttv3.MqttConnectOptions;
import org.eclipse.paho.client.mqttv3.MqttException;
import org.eclipse.paho.client.mqttv3.persist.MemoryPersistence;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.triad.vda5050.broker.MosquittoBroker;
import org.triad.vda5050.devices.DeviceLink;
import org.triad.vda5050.devices.DeviceMessages;
import org.triad.vda5050.mqtt.BrokerUnreachableException;
import org.triad.vda5050.mqtt.MqttLink;
import org.triad.vda5050.mqtt.Received;
import org.triad.vda5050.protocol.AgvState;
import org.triad.vda5050.protocol.Connection;
import org.triad.vda5050.protocol.Header;
import org.triad.vda5050.protocol.HeaderIds;
import org.triad.vda5050.protocol.InstantActions;
import org.triad.vda5050.protocol.Messages;
import org.triad.vda5050.protocol.Messages.ConnectionState;
import org.triad.vda5050.protocol.Order;
import org.triad.vda5050.protocol.Topic;
import org.triad.vda5050.protocol.VdaJson;

/**
 * A secured Mosquitto (TLS, client certificates, passwords, ACL) made from {@link BrokerCredentials}, attacked
 * the ways the open broker fell to: nobody without credentials gets in, and a robot with credentials can
 * neither command another robot nor speak for it.
 */
class SecuredBrokerTest {
    private static final String M = "triad";
    private static Path root;
    private static BrokerCredentials credentials;
    private static MosquittoBroker broker;

    @BeforeAll
    static void start() throws Exception {
        root = Files.createTempDirectory("triad-secured-broker");
        credentials = BrokerCredentials.ensure(root.resolve("credentials"), M, List.of("courier-1", "courier-2"));
        broker = MosquittoBroker.startSecured(root.resolve("broker"), MosquittoBroker.freePort(), credentials);
        System.setProperty(ClientCredentials.PROPERTY, credentials.dir().toString());
    }

    @AfterAll
    static void stop() {
        System.clearProperty(ClientCredentials.PROPERTY);
        broker.close();
    }

    @Test
    void theFolderIsMadeOnceAndKeepsWhatExists() throws Exception {
        assertEquals(List.of("building", "courier-1", "courier-2", "master"), credentials.identities());
        String caBefore = Files.readString(credentials.caCertificate());
        String pwBefore = Files.readString(root.resolve("credentials/clients/courier-1.password"));
        BrokerCredentials again = BrokerCredentials.ensure(root.resolve("credentials"), M, List.of("courier-1", "courier-3"));
        assertEquals(List.of("courier-3"), again.made());
        assertEquals(caBefore, Files.readString(again.caCertificate()));
        assertEquals(pwBefore, Files.readString(root.resolve("credentials/clients/courier-1.password")));
        String passwd = Files.readString(again.passwordFile());
        assertTrue(passwd.contains("courier-3:$"), "hashed: " + passwd);
        assertTrue(!passwd.contains(pwBefore.trim()), "no password in plain text in " + again.passwordFile());
        assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(root.resolve("credentials/ca.key"))));
        assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(again.passwordFile())));
        assertEquals("rwx------", PosixFilePermissions.toString(Files.getPosixFilePermissions(again.dir())));
        IllegalArgumentException bad = assertThrows(IllegalArgumentException.class,
                () -> BrokerCredentials.ensure(root.resolve("credentials"), M, List.of("a/b")));
        assertTrue(bad.getMessage().contains("not 'a/b'"), bad.getMessage());
        IllegalArgumentException reserved = assertThrows(IllegalArgumentException.class,
                () -> BrokerCredentials.ensure(root.resolve("credentials"), M, List.of(BrokerCredentials.BUILDING)));
        assertTrue(reserved.getMessage().contains("the building's identity"), reserved.getMessage());
    }

    /**
     * The device protocol on the secured broker: only the building's identity reads the requests and answers with
     * a device's state; a robot and master control ask and watch. A robot that forges a door's state, or listens to
     * what others ask, gets nothing through.
     */
    @Test
    void onlyTheBuildingAnswersForADevice() throws Exception {
        List<DeviceMessages.DoorRequest> buildingGot = new CopyOnWriteArrayList<>();
        List<DeviceMessages.DoorRequest> spyGot = new CopyOnWriteArrayList<>();
        List<DeviceMessages.DoorState> robotGot = new CopyOnWriteArrayList<>();
        List<DeviceMessages.DoorState> masterGot = new CopyOnWriteArrayList<>();
        List<String> problems = new CopyOnWriteArrayList<>();
        String request = DeviceMessages.doorRequestTopic("fireDoor");
        String state = DeviceMessages.doorStateTopic("fireDoor");
        java.util.concurrent.ExecutorService answers = java.util.concurrent.Executors.newSingleThreadExecutor();
        try (DeviceLink building = DeviceLink.connect(broker.url(), BrokerCredentials.BUILDING, "devices-building", problems::add);
                DeviceLink robot = DeviceLink.connect(broker.url(), "courier-1", "devices-courier-1", problems::add);
                DeviceLink other = DeviceLink.connect(broker.url(), "courier-2", "devices-courier-2", problems::add);
                DeviceLink master = DeviceLink.connect(broker.url(), BrokerCredentials.MASTER, "devices-master", problems::add)) {
            // answered off the MQTT callback thread, as the building does (a blocking publish there would wait for itself)
            building.subscribe(request, DeviceMessages.DoorRequest.class, r -> {
                buildingGot.add(r);
                answers.execute(() -> building.publish(state,
                        new DeviceMessages.DoorState("fireDoor", DeviceMessages.OPEN, r.requestId(), null, HeaderIds.now()), true));
            });
            other.subscribe(request, DeviceMessages.DoorRequest.class, spyGot::add);
            robot.subscribe(state, DeviceMessages.DoorState.class, robotGot::add);
            master.subscribe(state, DeviceMessages.DoorState.class, masterGot::add);

            // courier-2 answers for the door (dropped: it is not the building) and asks as the building would answer
            other.publish(state, new DeviceMessages.DoorState("fireDoor", DeviceMessages.CLOSED, "forged", null, HeaderIds.now()), true);
            building.publish(request, new DeviceMessages.DoorRequest("building-asks", "building", "fireDoor", DeviceMessages.CLOSED, HeaderIds.now()), false);
            // then courier-1 asks, and master control after it
            robot.publish(request, new DeviceMessages.DoorRequest("r1", "courier-1", "fireDoor", DeviceMessages.OPEN, HeaderIds.now()), false);
            master.publish(request, new DeviceMessages.DoorRequest("m1", "master", "fireDoor", DeviceMessages.OPEN, HeaderIds.now()), false);
            long end = System.nanoTime() + 60_000_000_000L;
            while (!(robotGot.stream().anyMatch(d -> "m1".equals(d.lastRequestId())) && masterGot.stream().anyMatch(d -> "m1".equals(d.lastRequestId())))
                    && System.nanoTime() < end) {
                Thread.sleep(25);
            }
            assertEquals(List.of("r1", "m1"), buildingGot.stream().map(DeviceMessages.DoorRequest::requestId).toList());
            assertEquals(List.of("r1", "m1"), robotGot.stream().map(DeviceMessages.DoorState::lastRequestId).toList(), "no forged state");
            assertEquals(List.of("r1", "m1"), masterGot.stream().map(DeviceMessages.DoorState::lastRequestId).toList());
            assertEquals(List.of(), spyGot, "a robot does not read what others ask");
            assertEquals(List.of(), problems);
        } finally {
            answers.shutdownNow();
        }
    }

    @Test
    void nobodyWithoutCredentialsGetsIn() throws Exception {
        String port = Integer.toString(broker.port());
        // plain TCP to the TLS port
        assertThrows(MqttException.class, () -> attacker("tcp://127.0.0.1:" + port, null, null, null));
        // TLS trusting the CA, no client certificate, anonymous
        assertThrows(MqttException.class, () -> attacker("ssl://127.0.0.1:" + port, trustOnly(), null, null));
        // a certificate the broker's CA did not issue, whatever name and password come with it
        BrokerCredentials foreign = BrokerCredentials.ensure(root.resolve("foreign"), M, List.of("courier-1"));
        MqttException wrong = assertThrows(MqttException.class,
                () -> attacker("ssl://127.0.0.1:" + port, foreign.client("courier-1").socketFactory(), "courier-1",
                        new String(foreign.client("courier-1").password())));
        assertNotNull(wrong);
        // the library's own connect: a broker that refuses says so, naming the identity
        System.setProperty(ClientCredentials.PROPERTY, root.resolve("nothing-here").toString());
        try {
            IllegalArgumentException none = assertThrows(IllegalArgumentException.class,
                    () -> MqttLink.connect(broker.url(), "courier-1", "c", null, line -> { }, 5, 5));
            assertTrue(none.getMessage().startsWith("no credentials for 'courier-1' in "), none.getMessage());
        } finally {
            System.setProperty(ClientCredentials.PROPERTY, credentials.dir().toString());
        }
        IllegalArgumentException noIdentity = assertThrows(IllegalArgumentException.class,
                () -> MqttLink.connect(broker.url(), "c", null, line -> { }, 5, 5));
        assertTrue(noIdentity.getMessage().contains("needs the client's identity"), noIdentity.getMessage());
    }

    @Test
    void aRobotCannotCommandOrSpeakForAnother() throws Exception {
        List<Received> robotGot = new CopyOnWriteArrayList<>();
        List<Received> masterGot = new CopyOnWriteArrayList<>();
        List<Received> spyGot = new CopyOnWriteArrayList<>();
        try (MqttLink robot = MqttLink.connect(broker.url(), "courier-1", "triad-agv-courier-1",
                new MqttLink.Will(Topic.CONNECTION.of(M, "courier-1"), connection("courier-1", ConnectionState.CONNECTIONBROKEN)), line -> { }, 5, 5);
                MqttLink master = MqttLink.connect(broker.url(), BrokerCredentials.MASTER, "triad-master-test", null, line -> { }, 5, 5);
                MqttLink other = MqttLink.connect(broker.url(), "courier-2", "triad-agv-courier-2", null, line -> { }, 5, 5)) {
            robot.subscribe(Topic.ORDER.of(M, "courier-1"), robotGot::add);
            robot.subscribe(Topic.INSTANT_ACTIONS.of(M, "courier-1"), robotGot::add);
            master.subscribe(Topic.CONNECTION.ofAll(), masterGot::add);
            master.subscribe(Topic.STATE.ofAll(), masterGot::add);
            // courier-2 listens in on courier-1's orders (denied: it receives nothing)
            other.subscribe(Topic.ORDER.of(M, "courier-1"), spyGot::add);

            // courier-2, authenticated, attacks courier-1 (each publication is acknowledged and dropped)
            other.publish(Topic.ORDER.of(M, "courier-1"), order("courier-1", "forged"), false);
            other.publish(Topic.INSTANT_ACTIONS.of(M, "courier-1"), startPause("courier-1"), false);
            other.publish(Topic.CONNECTION.of(M, "courier-1"), connection("courier-1", ConnectionState.CONNECTIONBROKEN), true);
            other.publish(Topic.STATE.of(M, "courier-1"), state("courier-1", Integer.MAX_VALUE, "forged"), false);
            // a robot may not command itself nor itself pose as master control
            other.publish(Topic.ORDER.of(M, "courier-2"), order("courier-2", "self"), false);

            // then the legitimate messages, on the same broker: they arrive, and nothing before them did
            master.publish(Topic.ORDER.of(M, "courier-1"), order("courier-1", "real"), false);
            robot.publish(Topic.STATE.of(M, "courier-1"), state("courier-1", 1, "real"), false);
            await(() -> robotGot.size() >= 1 && masterGot.stream().anyMatch(r -> r.address().topic() == Topic.STATE));
            assertEquals(1, robotGot.size(), robotGot.toString());
            assertEquals("real", robotGot.get(0).as(Order.class).orderId());
            List<Received> states = masterGot.stream().filter(r -> r.address().topic() == Topic.STATE).toList();
            assertEquals(1, states.size(), states.toString());
            assertEquals("real", states.get(0).as(AgvState.class).orderId());
            assertTrue(masterGot.stream().noneMatch(r -> r.address().topic() == Topic.CONNECTION), masterGot.toString());
            assertEquals(List.of(), spyGot);
        }
        // no forged retained CONNECTIONBROKEN waits for the next master control either
        List<Received> later = new CopyOnWriteArrayList<>();
        try (MqttLink master = MqttLink.connect(broker.url(), BrokerCredentials.MASTER, "triad-master-later", null, line -> { }, 5, 5);
                MqttLink robot = MqttLink.connect(broker.url(), "courier-1", "triad-agv-courier-1b", null, line -> { }, 5, 5)) {
            master.subscribe(Topic.CONNECTION.ofAll(), later::add);
            robot.publish(Topic.CONNECTION.of(M, "courier-1"), connection("courier-1", ConnectionState.ONLINE), true);
            await(() -> !later.isEmpty());
            assertEquals(List.of(ConnectionState.ONLINE), later.stream().map(r -> r.as(Connection.class).connectionState()).toList());
        }
    }

    /**
     * The login is the certificate's identity and the client id is the login: courier-2's certificate with
     * master's name and real password, or anonymous, is courier-2 (it can neither command courier-1 nor speak
     * for it), and under courier-1's client id it does not knock courier-1's session off.
     */
    @Test
    void aCertificateLogsInAsItsOwnIdentityOnly() throws Exception {
        List<Received> robotGot = new CopyOnWriteArrayList<>();
        List<Received> masterGot = new CopyOnWriteArrayList<>();
        List<String> robotProblems = new CopyOnWriteArrayList<>();
        String tls = "ssl://127.0.0.1:" + broker.port();
        String masterPassword = new String(credentials.client(BrokerCredentials.MASTER).password());
        try (MqttLink robot = MqttLink.connect(broker.url(), "courier-1", "triad-agv-courier-1", null, robotProblems::add, 5, 5);
                MqttLink master = MqttLink.connect(broker.url(), BrokerCredentials.MASTER, "triad-master-identity", null, line -> { }, 5, 5)) {
            robot.subscribe(Topic.ORDER.of(M, "courier-1"), robotGot::add);
            master.subscribe(Topic.STATE.ofAll(), masterGot::add);
            master.subscribe(Topic.CONNECTION.ofAll(), masterGot::add);

            // courier-2's certificate presenting master's name and password, under courier-1's client id
            impersonate(tls, credentials.client("courier-2").socketFactory(), BrokerCredentials.MASTER, masterPassword, "triad-agv-courier-1");
            // courier-2's certificate presenting courier-1's name, no password, under master's client id
            impersonate(tls, credentials.client("courier-2").socketFactory(), "courier-1", null, "triad-master-identity");
            // courier-2's certificate, anonymous
            impersonate(tls, credentials.client("courier-2").socketFactory(), null, null, "attacker-anonymous");

            master.publish(Topic.ORDER.of(M, "courier-1"), order("courier-1", "real"), false);
            robot.publish(Topic.STATE.of(M, "courier-1"), state("courier-1", 1, "real"), false);
            await(() -> robotGot.size() >= 1 && masterGot.stream().anyMatch(r -> r.address().topic() == Topic.STATE));
            assertEquals(List.of("real"), robotGot.stream().map(r -> r.as(Order.class).orderId()).toList());
            assertEquals(List.of("real"), masterGot.stream().filter(r -> r.address().topic() == Topic.STATE)
                    .map(r -> r.as(AgvState.class).orderId()).toList());
            assertTrue(masterGot.stream().filter(r -> r.address().topic() == Topic.CONNECTION)
                    .noneMatch(r -> r.as(Connection.class).connectionState() == ConnectionState.CONNECTIONBROKEN), masterGot.toString());
            assertTrue(robot.isConnected() && master.isConnected(), "a session was taken over: " + robotProblems);
            String log = Files.readString(broker.log());
            assertTrue(!log.contains("Client courier-1 already connected") && !log.contains("Client master already connected"),
                    "a session was taken over:\n" + log);
            assertTrue(log.contains("u'courier-2'"), "the attacker logged in as the certificate's identity:\n" + log);
        }
    }

    /** Connects with a robot's certificate as someone else, then orders, pauses and speaks for courier-1. */
    private static void impersonate(String url, SSLSocketFactory tls, String user, String password, String clientId) throws Exception {
        MqttClient c = new MqttClient(url, clientId, new MemoryPersistence());
        try {
            MqttConnectOptions o = new MqttConnectOptions();
            o.setConnectionTimeout(10);
            o.setSocketFactory(tls);
            if (user != null) {
                o.setUserName(user);
                o.setPassword(password == null ? new char[0] : password.toCharArray());
            }
            c.connect(o); // the certificate is valid: it logs in, as courier-2
            c.publish(Topic.ORDER.of(M, "courier-1"), VdaJson.write(VdaJson.tree(order("courier-1", "forged"))), 1, false);
            c.publish(Topic.INSTANT_ACTIONS.of(M, "courier-1"), VdaJson.write(VdaJson.tree(startPause("courier-1"))), 1, false);
            c.publish(Topic.STATE.of(M, "courier-1"), VdaJson.write(VdaJson.tree(state("courier-1", Integer.MAX_VALUE, "forged"))), 1, false);
            c.publish(Topic.CONNECTION.of(M, "courier-1"),
                    VdaJson.write(VdaJson.tree(connection("courier-1", ConnectionState.CONNECTIONBROKEN))), 1, true);
            c.disconnect();
        } finally {
            c.close(true);
        }
    }

    @Test
    void anUnauthenticatedClientSeesARefusalNamingIt() {
        System.setProperty(ClientCredentials.PROPERTY, root.resolve("credentials").toString());
        BrokerUnreachableException e = assertThrows(BrokerUnreachableException.class,
                () -> MqttLink.connect("ssl://127.0.0.1:" + MosquittoBroker.freePort(), "courier-1", "x", null, line -> { }, 5, 2));
        assertTrue(e.getMessage().startsWith("no MQTT broker at 127.0.0.1:"), e.getMessage());
    }

    private static void attacker(String url, SSLSocketFactory tls, String user, String password) throws MqttException {
        MqttClient c = new MqttClient(url, "attacker-" + System.nanoTime(), new MemoryPersistence());
        try {
            MqttConnectOptions o = new MqttConnectOptions();
            o.setConnectionTimeout(5);
            if (tls != null) {
                o.setSocketFactory(tls);
            }
            if (user != null) {
                o.setUserName(user);
                o.setPassword(password.toCharArray());
            }
            c.connect(o);
            // connected: it should not have been; show what it could do
            c.publish(Topic.ORDER.of(M, "courier-1"), VdaJson.write(VdaJson.tree(order("courier-1", "attack"))), 1, false);
            c.disconnect();
        } finally {
            c.close(true);
        }
    }

    private static SSLSocketFactory trustOnly() throws Exception {
        var trust = java.security.KeyStore.getInstance("PKCS12");
        trust.load(null, null);
        trust.setCertificateEntry("ca", Certificates.readCertificate(credentials.caCertificate()));
        var tmf = javax.net.ssl.TrustManagerFactory.getInstance(javax.net.ssl.TrustManagerFactory.getDefaultAlgorithm());
        tmf.init(trust);
        SSLContext tls = SSLContext.getInstance("TLS");
        tls.init(null, tmf.getTrustManagers(), null);
        return tls.getSocketFactory();
    }

    static Connection connection(String serial, ConnectionState s) {
        return new Connection(0, HeaderIds.now(), Header.VERSION, M, serial, s);
    }

    static Order order(String serial, String orderId) {
        return new Order(1, HeaderIds.now(), Header.VERSION, M, serial, orderId, 0, null,
                List.of(new Messages.Node("lobby", 0, null, true, null, List.of()), new Messages.Node("c4", 2, null, true, null, List.of())),
                List.of(new Messages.Edge("lobby-c4", 1, null, true, "lobby", "c4", List.of())));
    }

    static InstantActions startPause(String serial) {
        return new InstantActions(1, HeaderIds.now(), Header.VERSION, M, serial,
                List.of(new Messages.Action("startPause", "pause-1", null, Messages.BlockingType.HARD, null)));
    }

    static AgvState state(String serial, int headerId, String orderId) {
        return new AgvState(headerId, HeaderIds.now(), Header.VERSION, M, serial, orderId, 0, null, "lobby", 0, List.of(), List.of(), null,
                null, null, false, null, null, null, List.of(), new Messages.BatteryState(80, false), "AUTOMATIC", List.of(), null,
                new Messages.SafetyState("NONE", false));
    }

    private static void await(BooleanSupplier c) throws InterruptedException {
        for (int i = 0; i < 400 && !c.getAsBoolean(); i++) {
            Thread.sleep(25);
        }
    }

    @SuppressWarnings("unused")
    private static byte[] utf8(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }
}
