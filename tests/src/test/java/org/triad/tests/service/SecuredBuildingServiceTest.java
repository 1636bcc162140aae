package org.triad.tests.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.examples.hospital.vda5050.HospitalAgvMain;
import org.triad.service.AccessTokens;
import org.triad.service.TriadService;
import org.triad.service.Views.TaskView;
import org.triad.vda5050.broker.MosquittoBroker;
import org.triad.vda5050.master.MasterControl;
import org.triad.vda5050.security.BrokerCredentials;
import org.triad.vda5050.security.ClientCredentials;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * The deployable hospital on the secured broker of {@code ./triad broker} ({@code ssl://}, client certificates, the
 * ACL): the building (its own JVM) serves the couriers as their identities and the doors and lift as
 * {@code building}; the service drives the courier as {@code master} and asks the pharmacy door and the lift over
 * master control's one connection. A delivery from the pharmacy (floor 0, behind its door) to ward 4 (floor 1)
 * completes under traffic control (the ride a reserved edge of the traffic map), and the operator's {@code /api/devices}
 * shows the door closed behind the courier and the lift at floor 1.
 * A real Mosquitto with TLS, the real service, the couriers speaking VDA 5050.
 */
class SecuredBuildingServiceTest {
    private static final Path HOSPITAL = Path.of("../models/hospital/src/main/models").toAbsolutePath().normalize();
    private static final String OPERATOR = "secured-operator-token";
    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path dir;

    @AfterEach
    void forgetCredentials() {
        System.clearProperty(ClientCredentials.PROPERTY);
    }

    @Test
    void aDeliveryThroughThePharmacyDoorAndTheLiftOnTheSecuredBroker() throws Exception {
        BrokerCredentials credentials = BrokerCredentials.ensure(dir.resolve("credentials"), MasterControl.TRIAD, List.of("courier-1"));
        Path buildingLog = dir.resolve("building.log");
        Process building = null;
        try (MosquittoBroker broker = MosquittoBroker.startSecured(dir.resolve("broker"), MosquittoBroker.freePort(), credentials)) {
            assertTrue(broker.url().startsWith("ssl://"), broker.url());
            building = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx256m",
                    "-D" + ClientCredentials.PROPERTY + "=" + credentials.dir(), "-cp", System.getProperty("java.class.path"),
                    HospitalAgvMain.class.getName(), "--broker", broker.url(), "--serial", "courier-1", "--speed", "20")
                    .redirectErrorStream(true).redirectOutput(buildingLog.toFile()).start();
            awaitLine(buildingLog, "building: one hospital", building);
            System.setProperty(ClientCredentials.PROPERTY, credentials.dir().toString()); // the service is master control
            // under traffic control (the default): the ride is a reserved edge of the traffic map, c7 -> d1
            TriadService.Options o = new TriadService.Options(HOSPITAL, List.of("vda5050:" + broker.url() + ",wait=10,silence=30"), null, dir.resolve("db"),
                    null, "127.0.0.1", 0, Map.of(AccessTokens.SUBMIT_ENV, "secured-submit-token", AccessTokens.OPERATOR_ENV, OPERATOR));
            try (TriadService s = TriadService.start(o)) {
                assertEquals(List.of("courier-1"), s.fleet().robots().stream().map(r -> r.name()).toList());
                ObjectNode task = JSON.createObjectNode().put("task", "CollectAndDeliver");
                task.putObject("args").put("i", "insulin").put("from", "pharmacy").put("to", "ward4");
                long id = s.fleet().submit(task).id();
                TaskView t = awaitEnd(s, id);
                assertEquals("completed", t.state(), t + "\n" + Files.readString(buildingLog));
                ApiClient api = new ApiClient("http://127.0.0.1:" + s.port(), OPERATOR);
                // the door was closed behind the courier before its passDoor succeeded, and the lift's last state
                // (at floor 1) came before the courier drove out: both on master control's connection before the task ended
                JsonNode devices = JSON.readTree(api.get("/api/devices"));
                JsonNode door = device(devices, "door", "pharmacyDoor");
                assertEquals("CLOSED", door.path("state").asText(), devices.toString());
                JsonNode lift = device(devices, "lift", "lift");
                assertEquals("STOPPED", lift.path("state").asText(), devices.toString());
                assertTrue(lift.path("detail").asText().contains("at floor 1"), devices.toString());
            }
            // under traffic control the ride is the edge c7 -> d1 with its action 'ride' (the building brings the cabin)
            String log = Files.readString(buildingLog);
            assertTrue(log.contains(" c7 -ride-> d1") && log.contains("finished at d1"), log);
        } finally {
            if (building != null) {
                building.destroy();
                if (!building.waitFor(30, TimeUnit.SECONDS)) {
                    building.destroyForcibly().waitFor(30, TimeUnit.SECONDS);
                }
            }
        }
    }

    private static JsonNode device(JsonNode devices, String kind, String name) {
        for (JsonNode d : devices) {
            if (d.path("kind").asText().equals(kind) && d.path("name").asText().equals(name)) {
                return d;
            }
        }
        throw new AssertionError("no " + kind + " '" + name + "' on /api/devices: " + devices);
    }

    private static TaskView awaitEnd(TriadService s, long id) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(240);
        while (true) {
            TaskView t = s.fleet().task(id).orElseThrow();
            if (Set.of("completed", "aborted", "refused").contains(t.state())) {
                return t;
            }
            assertTrue(System.nanoTime() < deadline, "task " + id + " did not end: " + t);
            Thread.sleep(50);
        }
    }

    private static void awaitLine(Path log, String text, Process p) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(90);
        while (!(Files.exists(log) && Files.readString(log).contains(text))) {
            assertTrue(p.isAlive() && System.nanoTime() < deadline, "no '" + text + "': " + (Files.exists(log) ? Files.readString(log) : ""));
            Thread.sleep(100);
        }
    }
}
