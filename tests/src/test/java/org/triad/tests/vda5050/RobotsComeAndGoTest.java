package org.triad.tests.vda5050;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.Predicate;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.examples.hospital.vda5050.SimulatedAgv;
import org.triad.service.AccessTokens;
import org.triad.service.TriadService;
import org.triad.service.Views.RobotView;
import org.triad.service.Views.TaskView;
import org.triad.vda5050.broker.MosquittoBroker;
import org.triad.vda5050.master.MasterControl;
import org.triad.vda5050.mqtt.MqttLink;
import org.triad.vda5050.protocol.Connection;
import org.triad.vda5050.protocol.Header;
import org.triad.vda5050.protocol.HeaderIds;
import org.triad.vda5050.protocol.Messages.ConnectionState;
import org.triad.vda5050.protocol.Topic;
import org.triad.vda5050.protocol.VdaJson;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * AGVs that come and go while {@code triad serve --robots vda5050:...} runs (a real Mosquitto, simulated
 * couriers speaking VDA 5050): one that comes later is dispatched to; one that goes OFFLINE mid-task leaves
 * the fleet and its task ends aborted with that cause (a remote-operation request, not lost), and it is
 * back when it reports again; an AGV with a serial number the configuration does not allow, or whose
 * factsheet lacks an action the hospital needs, is refused with the reason and never dispatched to.
 */
class RobotsComeAndGoTest {
	private static final Path HOSPITAL = Path.of("../models/hospital/src/main/models").toAbsolutePath().normalize();
	private static final ObjectMapper JSON = new ObjectMapper();
	private static final long PATIENCE_NANOS = 120_000_000_000L;

	@TempDir
	Path dir;

	@Test
	void agvsThatComeLaterAreDispatchedToThoseThatGoAreTakenOutAndBadOnesAreRefusedWithTheReason() throws Exception {
		try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"));
				SimulatedAgv c1 = new SimulatedAgv(broker.url(), "courier-1", 42, 50, null, line -> { }).start();
				TriadService s = TriadService.start(new TriadService.Options(HOSPITAL, List.of("vda5050:" + broker.url() + ",wait=1,allow=courier-*,silence=30"),
						null, dir.resolve("db"), null, "127.0.0.1", 0,
						Map.of(AccessTokens.SUBMIT_ENV, "submit-token-for-tests", AccessTokens.OPERATOR_ENV, "operator-token-for-tests")))) {
			assertEquals(List.of("courier-1"), s.fleet().robots().stream().map(RobotView::name).toList());

			// a courier that comes later joins and is dispatched to
			SimulatedAgv c2 = new SimulatedAgv(broker.url(), "courier-2", 43, 5, null, line -> { }).start();
			try {
				awaitRobot(s, "courier-2", r -> r.presence().equals("online"));
				s.fleet().setOnline("courier-1", false);
				TaskView toWard1 = awaitEnd(s, submit(s, JSON.createObjectNode().put("dst", "ward1")));
				assertEquals("completed", toWard1.state(), toWard1.toString());
				assertEquals("courier-2", toWard1.robot());
				RobotView seen = awaitRobot(s, "courier-2", r -> r.pose() != null && r.battery() != null);
				assertEquals(SimulatedAgv.MAP_ID, seen.pose().mapId(), "its position as its state reports it: " + seen);

				// bad input: refused with the reason, on the operator's list and never dispatched to
				try (MqttLink intruder = fakeAgv(broker.url(), "forklift-9", Set.of("pick", "drop", "guide", "startFollowing"));
						MqttLink lacking = fakeAgv(broker.url(), "courier-3", Set.of("drop", "guide"))) {
					RobotView f = awaitRobot(s, "forklift-9", r -> r.presence().equals("refused"));
					assertTrue(f.offlineReason().contains("serial number 'forklift-9' is not allowed by the configuration (allowed: courier-*)"), f.offlineReason());
					RobotView l = awaitRobot(s, "courier-3", r -> r.presence().equals("refused"));
					assertTrue(l.offlineReason().contains("its factsheet lacks the actions pick, startFollowing that the application needs"), l.offlineReason());
					assertTrue(!l.online() && !f.online());
				}

				// a courier that goes OFFLINE mid-task: out of dispatch, its task aborted with that cause, not lost
				long toWard3 = submit(s, JSON.createObjectNode().put("dst", "ward3"));
				awaitTask(s, toWard3, t -> t.events().stream().anyMatch(e -> e.kind().equals("action_started")));
				c2.close();
				c2 = null;
				TaskView lost = awaitEnd(s, toWard3);
				assertEquals("aborted", lost.state(), lost.toString());
				assertTrue(lost.reason().contains("OFFLINE"), lost.reason());
				assertTrue(s.fleet().requests(false).stream().anyMatch(r -> r.task() == toWard3 && r.reason().contains("OFFLINE")),
						"the operator is asked to decide: " + s.fleet().requests(false));
				RobotView gone = awaitRobot(s, "courier-2", r -> r.presence().equals("gone"));
				assertTrue(gone.offlineReason().contains("AGV triad/courier-2 reported OFFLINE"), gone.offlineReason());
			} finally {
				if (c2 != null) {
					c2.close();
				}
			}
			// ... and back when it reports again
			try (SimulatedAgv again = new SimulatedAgv(broker.url(), "courier-2", 44, 50, null, line -> { }).start()) {
				awaitRobot(s, "courier-2", r -> r.presence().equals("online"));
			}
		}
	}

	/** An AGV that only announces itself ONLINE with a factsheet listing these actions (it never reports a state). */
	private static MqttLink fakeAgv(String broker, String serial, Set<String> actions) {
		MqttLink link = MqttLink.connect(broker, "fake-" + serial, null, line -> { }, 5, 10);
		link.publish(Topic.CONNECTION.of(MasterControl.TRIAD, serial),
				new Connection(1, HeaderIds.now(), Header.VERSION, MasterControl.TRIAD, serial, ConnectionState.ONLINE), true);
		ObjectNode f = VdaJson.mapper().createObjectNode();
		f.put("headerId", 1).put("timestamp", HeaderIds.now()).put("version", Header.VERSION).put("manufacturer", MasterControl.TRIAD)
				.put("serialNumber", serial);
		ObjectNode type = f.putObject("typeSpecification");
		type.put("seriesName", "fake").put("agvKinematic", "DIFF").put("agvClass", "CARRIER").put("maxLoadMass", 5);
		type.putArray("localizationTypes").add("NATURAL");
		type.putArray("navigationTypes").add("AUTONOMOUS");
		f.putObject("physicalParameters").put("speedMin", 0).put("speedMax", 1).put("accelerationMax", 1).put("decelerationMax", 1)
				.put("heightMax", 1).put("width", 0.5).put("length", 0.5);
		ObjectNode limits = f.putObject("protocolLimits");
		limits.putObject("maxStringLens");
		limits.putObject("maxArrayLens");
		limits.putObject("timing").put("minOrderInterval", 0.1).put("minStateInterval", 0.1).put("defaultStateInterval", 1.0);
		ObjectNode features = f.putObject("protocolFeatures");
		features.putArray("optionalParameters");
		ArrayNode list = features.putArray("agvActions");
		for (String a : actions) {
			ObjectNode o = list.addObject();
			o.put("actionType", a);
			o.putArray("actionScopes").add("NODE");
		}
		f.putObject("agvGeometry");
		f.putObject("loadSpecification").putArray("loadPositions").add("tray");
		link.publish(Topic.FACTSHEET.of(MasterControl.TRIAD, serial), f, true);
		return link;
	}

	private static long submit(TriadService s, ObjectNode args) {
		return s.fleet().submit(JSON.createObjectNode().put("task", "GoTo").set("args", args)).id();
	}

	private static TaskView awaitEnd(TriadService s, long id) throws InterruptedException {
		return awaitTask(s, id, t -> Set.of("completed", "aborted", "refused").contains(t.state()));
	}

	private static TaskView awaitTask(TriadService s, long id, Predicate<TaskView> until) throws InterruptedException {
		long deadline = System.nanoTime() + PATIENCE_NANOS;
		while (true) {
			TaskView t = s.fleet().task(id).orElseThrow();
			if (until.test(t)) {
				return t;
			}
			assertTrue(System.nanoTime() < deadline, "task " + id + " did not get there: " + t);
			Thread.sleep(50);
		}
	}

	private static RobotView awaitRobot(TriadService s, String name, Predicate<RobotView> until) throws InterruptedException {
		long deadline = System.nanoTime() + PATIENCE_NANOS;
		while (true) {
			Optional<RobotView> r = s.fleet().robots().stream().filter(v -> v.name().equals(name)).findFirst();
			if (r.isPresent() && until.test(r.get())) {
				return r.get();
			}
			assertTrue(System.nanoTime() < deadline, "robot " + name + " did not get there: " + s.fleet().robots());
			Thread.sleep(50);
		}
	}
}
