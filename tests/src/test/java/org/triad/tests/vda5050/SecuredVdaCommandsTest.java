package org.triad.tests.vda5050;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import org.eclipse.paho.client.mqttv3.MqttClient;
import org.eclipse.paho.client.mqttv3.MqttConnectOptions;
import org.eclipse.paho.client.mqttv3.MqttException;
import org.eclipse.paho.client.mqttv3.persist.MemoryPersistence;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.triad.cli.TriadCli;
import org.triad.examples.hospital.vda5050.SimulatedAgv;
import org.triad.vda5050.broker.MosquittoBroker;
import org.triad.vda5050.master.MasterControl;
import org.triad.vda5050.mqtt.MqttLink;
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
import org.triad.vda5050.security.BrokerCredentials;
import org.triad.vda5050.security.ClientCredentials;

/**
 * The issue's attacks on a simulated courier behind the secured broker of {@code ./triad broker}: a client
 * without credentials cannot connect at all, and another robot's identity can neither drive the courier,
 * pause it, knock it offline with a retained CONNECTIONBROKEN, nor blind master control with a state whose
 * headerId is 2147483647; the task then runs as ever through {@code ./triad run --credentials}.
 */
class SecuredVdaCommandsTest {
	private static final String HOSPITAL = "../models/hospital/src/main/models";
	private static final String M = MasterControl.TRIAD;
	private Path root;
	private BrokerCredentials credentials;
	private MosquittoBroker broker;

	private record Result(int code, List<String> lines, String err) {
	}

	@BeforeEach
	void start() throws Exception {
		root = Files.createTempDirectory("triad-secured-vda");
		credentials = BrokerCredentials.ensure(root.resolve("credentials"), M, List.of("courier-7", "courier-8"));
		broker = MosquittoBroker.startSecured(root.resolve("broker"), MosquittoBroker.freePort(), credentials);
		// the simulated courier runs in this JVM: it reads its credentials where the CLI would put them
		System.setProperty(ClientCredentials.PROPERTY, credentials.dir().toString());
	}

	@AfterEach
	void stop() {
		System.clearProperty(ClientCredentials.PROPERTY);
		broker.close();
	}

	private static Result triad(String... args) {
		StringWriter out = new StringWriter();
		StringWriter err = new StringWriter();
		int code = TriadCli.execute(args, new PrintWriter(out, true), new PrintWriter(err, true));
		return new Result(code, Arrays.asList(out.toString().split("\\R")), err.toString());
	}

	@Test
	void attacksFailAndTheTaskRunsWithCredentials() throws Exception {
		List<AgvState> states = new CopyOnWriteArrayList<>();
		List<ConnectionState> connections = new CopyOnWriteArrayList<>();
		try (SimulatedAgv robot = new SimulatedAgv(broker.url(), "courier-7", 42, 50, null, line -> { }).start()) {
			// master control's identity observes first; it has one connection at a time (the broker's client id is
			// the identity), so the observer leaves before './triad run' logs in as master control
			try (MqttLink observer = MqttLink.connect(broker.url(), BrokerCredentials.MASTER, "observer", null, line -> { }, 5, 5)) {
				observer.subscribe(Topic.STATE.of(M, "courier-7"), r -> states.add(r.as(AgvState.class)));
				observer.subscribe(Topic.CONNECTION.of(M, "courier-7"), r -> connections.add(r.as(Connection.class).connectionState()));
				String port = Integer.toString(broker.port());
				// without credentials: not even a connection
				assertThrows(MqttException.class, () -> anonymous("tcp://127.0.0.1:" + port));
				assertThrows(MqttException.class, () -> anonymous("ssl://127.0.0.1:" + port));
				// with another robot's credentials: every attack is dropped by the broker
				try (MqttLink other = MqttLink.connect(broker.url(), "courier-8", "triad-agv-courier-7", null, line -> { }, 5, 5)) {
					other.publish(Topic.ORDER.of(M, "courier-7"), order("courier-7", "attack"), false);
					other.publish(Topic.INSTANT_ACTIONS.of(M, "courier-7"), new InstantActions(1, HeaderIds.now(), Header.VERSION, M, "courier-7",
							List.of(new Messages.Action("startPause", "pause-1", null, Messages.BlockingType.HARD, null))), false);
					other.publish(Topic.CONNECTION.of(M, "courier-7"),
							new Connection(Integer.MAX_VALUE, HeaderIds.now(), Header.VERSION, M, "courier-7", ConnectionState.CONNECTIONBROKEN), true);
					for (int i = 0; i < 5; i++) {
						other.publish(Topic.STATE.of(M, "courier-7"), forgedState("courier-7"), false);
					}
				}
				// the courier's own states (at least one a second) go on; none shows the forged order, a pause or the forged headerId
				int seen = states.size();
				await(() -> states.size() >= seen + 3);
				assertTrue(states.size() >= seen + 3, "the courier kept reporting: " + states.size());
				for (AgvState s : states) {
					assertFalse("attack".equals(s.orderId()) || "forged".equals(s.orderId()), s.toString());
					assertFalse(Boolean.TRUE.equals(s.paused()), s.toString());
					assertTrue(s.headerId() < Integer.MAX_VALUE, s.toString());
				}
				assertFalse(connections.contains(ConnectionState.CONNECTIONBROKEN), connections.toString());
			}
			// master control with credentials, through the CLI: the task completes
			Result r = triad("run", HOSPITAL, "--state", "Morning.state", "--task", "GoTo(ward3)", "--robots", "vda5050:" + broker.url(),
					"--serial", "courier-7", "--credentials", credentials.dir().toString());
			assertEquals(0, r.code(), String.join("\n", r.lines()) + r.err());
			assertEquals("task GoTo(ward3) completed", r.lines().get(r.lines().size() - 1));
			assertFalse(r.err().contains("warning"), r.err());
		}
	}

	@Test
	void aSecuredBrokerWithoutCredentialsIsOneLineAndExitCode2() {
		System.clearProperty(ClientCredentials.PROPERTY);
		Result r = triad("run", HOSPITAL, "--state", "Morning.state", "--task", "GoTo(ward3)", "--robots", "vda5050:" + broker.url(),
				"--credentials", root.resolve("elsewhere").toString());
		assertEquals(2, r.code());
		assertEquals("triad run: no credentials for 'master' in " + root.resolve("elsewhere") + ": ca.crt is missing (./triad broker"
				+ " --credentials " + root.resolve("elsewhere") + " makes them)", r.err().strip()); // master is always made, no --robots needed
	}

	private static void anonymous(String url) throws MqttException {
		MqttClient c = new MqttClient(url, "attacker", new MemoryPersistence());
		try {
			MqttConnectOptions o = new MqttConnectOptions();
			o.setConnectionTimeout(5);
			c.connect(o);
			c.publish(Topic.ORDER.of(M, "courier-7"), VdaJson.write(VdaJson.tree(order("courier-7", "attack"))), 1, false);
			c.disconnect();
		} finally {
			c.close(true);
		}
	}

	private static Order order(String serial, String orderId) {
		return new Order(1, HeaderIds.now(), Header.VERSION, M, serial, orderId, 0, null,
				List.of(new Messages.Node("lobby", 0, null, true, null, List.of()), new Messages.Node("c4", 2, null, true, null, List.of())),
				List.of(new Messages.Edge("lobby-c4", 1, null, true, "lobby", "c4", List.of())));
	}

	private static AgvState forgedState(String serial) {
		return new AgvState(Integer.MAX_VALUE, HeaderIds.now(), Header.VERSION, M, serial, "forged", 0, null, "lobby", 0, List.of(), List.of(),
				null, null, null, false, null, null, null, List.of(), new Messages.BatteryState(80, false), "AUTOMATIC", List.of(), null,
				new Messages.SafetyState("NONE", false));
	}

	private static void await(java.util.function.BooleanSupplier c) throws InterruptedException {
		for (int i = 0; i < 600 && !c.getAsBoolean(); i++) {
			Thread.sleep(25);
		}
	}
}
