package org.triad.tests.vda5050;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.examples.hospital.vda5050.SimulatedAgv;
import org.triad.service.AccessTokens;
import org.triad.service.ServiceError;
import org.triad.service.TriadService;
import org.triad.service.Views.TaskView;
import org.triad.vda5050.broker.MosquittoBroker;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * {@code triad serve --robots vda5050:tcp://HOST:PORT}: the service finds the hospital couriers ONLINE on a
 * real Mosquitto and dispatches to them as one building (a real broker, simulated AGVs speaking VDA 5050).
 */
class ServiceOnVdaTest {
	private static final Path HOSPITAL = Path.of("../models/hospital/src/main/models").toAbsolutePath().normalize();
	private static final ObjectMapper JSON = new ObjectMapper();

	@TempDir
	Path dir;

	private TriadService.Options options(String robots) {
		return new TriadService.Options(HOSPITAL, List.of(robots), null, dir.resolve("db"), null, "127.0.0.1", 0,
				Map.of(AccessTokens.SUBMIT_ENV, "submit-token-for-tests", AccessTokens.OPERATOR_ENV, "operator-token-for-tests"));
	}

	private static TaskView awaitEnd(TriadService s, long id) throws InterruptedException {
		long deadline = System.nanoTime() + 120_000_000_000L;
		while (true) {
			TaskView t = s.fleet().task(id).orElseThrow();
			if (Set.of("completed", "aborted", "refused").contains(t.state())) {
				return t;
			}
			assertTrue(System.nanoTime() < deadline, "task " + id + " did not end: " + t);
			Thread.sleep(50);
		}
	}

	private static long submit(TriadService s, String task, ObjectNode args) {
		return s.fleet().submit(JSON.createObjectNode().put("task", task).set("args", args)).id();
	}

	@Test
	void theServiceDrivesTheCouriersItFindsOnTheBrokerAsOneBuilding() throws Exception {
		try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"));
				SimulatedAgv c1 = new SimulatedAgv(broker.url(), "courier-1", 42, 50, null, line -> { }).start();
				SimulatedAgv c2 = new SimulatedAgv(broker.url(), "courier-2", 42, 50, null, line -> { }).start();
				TriadService s = TriadService.start(options("vda5050:" + broker.url() + ",wait=1,silence=30"))) {
			assertEquals(List.of("courier-1", "courier-2"), s.fleet().robots().stream().map(r -> r.name()).sorted().toList());
			long toWard1 = submit(s, "GoTo", JSON.createObjectNode().put("dst", "ward1"));
			long toWard3 = submit(s, "GoTo", JSON.createObjectNode().put("dst", "ward3"));
			TaskView a = awaitEnd(s, toWard1);
			TaskView b = awaitEnd(s, toWard3);
			assertEquals("completed", a.state(), a.toString());
			assertEquals("completed", b.state(), b.toString());
			assertEquals(Set.of("courier-1", "courier-2"), new TreeSet<>(List.of(a.robot(), b.robot())), "both couriers worked");

			ObjectNode gauze = JSON.createObjectNode().put("i", "gauze").put("from", "storage").put("to", "ward2");
			long first = submit(s, "CollectAndDeliver", gauze);
			long second = submit(s, "CollectAndDeliver", gauze.deepCopy());
			TaskView delivered = awaitEnd(s, first);
			TaskView refused = awaitEnd(s, second);
			assertEquals("completed", delivered.state(), delivered.toString());
			assertEquals("refused", refused.state(), "one gauze is delivered once: " + refused);
			assertTrue(refused.reason().contains("Delivered(gauze, ward2) holds now"), refused.reason());
		}
	}

	@Test
	void noCourierOnTheBrokerIsAStartupErrorSayingHowToStartOne() {
		try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"))) {
			ServiceError e = assertThrows(ServiceError.class, () -> TriadService.start(options("vda5050:" + broker.url() + ",wait=0.5")));
			assertTrue(e.getMessage().contains("no hospital courier (manufacturer 'triad') announced itself ONLINE on " + broker.url()), e.getMessage());
			assertTrue(e.getMessage().contains("./triad robot --broker " + broker.url() + " --count N"), e.getMessage());
		}
	}
}
