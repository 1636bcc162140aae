package org.triad.tests.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.examples.hospital.vda5050.HospitalAgvMain;
import org.triad.service.AccessTokens;
import org.triad.service.TriadService;
import org.triad.service.Views.TaskView;
import org.triad.vda5050.broker.MosquittoBroker;
import org.triad.vda5050.devices.DeviceLink;
import org.triad.vda5050.devices.DeviceMessages;
import org.triad.vda5050.devices.DeviceMessages.DoorState;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * {@code triad serve --robots vda5050:...} drives the couriers under traffic control (issue #21): two couriers of
 * one simulated building (one dyn4j world, its own JVM) leave the lobby at once for storage and x-ray, through
 * the one lobby door and the single-lane west corridor. One waits for the other (the operator's
 * {@code /api/traffic} shows it, with the reason), both arrive, and the building reports no contact between them.
 * The doors are tied to the reservations: the lobby door is not closed on the second courier waiting for it, and
 * each door is closed once nobody holds or waits for it.
 * A real Mosquitto, the real service, the couriers speaking VDA 5050.
 */
class ServiceTrafficOnVdaTest {
    private static final Path HOSPITAL = Path.of("../models/hospital/src/main/models").toAbsolutePath().normalize();
    private static final String OPERATOR = "traffic-operator-token";
    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path dir;

    @Test
    void twoCouriersLeavingTheLobbyAtOnceShareItsDoorAndTheWestCorridorWithoutContact() throws Exception {
        Path buildingLog = dir.resolve("building.log");
        Process building = null;
        try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"))) {
            List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx256m", "-cp",
                    System.getProperty("java.class.path"), HospitalAgvMain.class.getName(), "--broker", broker.url(), "--count", "2", "--speed", "4"));
            building = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(buildingLog.toFile()).start();
            awaitLine(buildingLog, "building: one hospital", building);
            TriadService.Options o = new TriadService.Options(HOSPITAL, List.of("vda5050:" + broker.url() + ",wait=1,silence=30"), null, dir.resolve("db"), null,
                    "127.0.0.1", 0, Map.of(AccessTokens.SUBMIT_ENV, "traffic-submit-token", AccessTokens.OPERATOR_ENV, OPERATOR));
            // the doors as the building reports them (retained states, then every change)
            Map<String, List<String>> doorModes = new java.util.concurrent.ConcurrentHashMap<>();
            try (DeviceLink doors = DeviceLink.connect(broker.url(), "traffic-test-doors", line -> { });
                    TriadService s = TriadService.start(o)) {
                for (String d : List.of("lobbyDoor", "storageDoor", "xrayDoor")) {
                    doors.subscribe(DeviceMessages.doorStateTopic(d), DoorState.class,
                            st -> doorModes.computeIfAbsent(d, k -> new CopyOnWriteArrayList<>()).add(st.currentMode()));
                }
                assertEquals(List.of("courier-1", "courier-2"), s.fleet().robots().stream().map(r -> r.name()).sorted().toList());
                ApiClient api = new ApiClient("http://127.0.0.1:" + s.port(), OPERATOR);
                List<JsonNode> waits = new CopyOnWriteArrayList<>();
                AtomicBoolean watching = new AtomicBoolean(true);
                Thread watcher = new Thread(() -> {
                    while (watching.get()) {
                        try {
                            JSON.readTree(api.get("/api/traffic?over=0")).forEach(waits::add);
                            Thread.sleep(30);
                        } catch (InterruptedException e) {
                            return;
                        } catch (Exception e) {
                            waits.add(JSON.createObjectNode().put("error", e.toString()));
                        }
                    }
                }, "traffic-watcher");
                watcher.start();
                long storage = submit(s, "storage");
                long xray = submit(s, "xray");
                TaskView a = awaitEnd(s, storage, xray);
                TaskView b = awaitEnd(s, xray, storage);
                watching.set(false);
                watcher.join(10_000);
                assertEquals("completed", a.state(), a + "\n" + Files.readString(buildingLog));
                assertEquals("completed", b.state(), b + "\n" + Files.readString(buildingLog));
                assertEquals(Set.of("courier-1", "courier-2"), Set.of(a.robot(), b.robot()), "both couriers drove");
                assertFalse(waits.stream().anyMatch(w -> w.has("error")), "the operator's traffic list answered: " + waits);
                // traffic control keeps the doors: the lobby door stayed open while the second courier waited for
                // it behind the first, and was closed once, after both; each room's door was closed behind its courier
                awaitClosed(doorModes, "lobbyDoor", buildingLog);
                assertEquals(1, closings(doorModes.get("lobbyDoor")),
                        "the lobby door was closed once, after both couriers, not on the second: " + doorModes);
                awaitClosed(doorModes, "storageDoor", buildingLog);
                awaitClosed(doorModes, "xrayDoor", buildingLog);
                assertTrue(waits.stream().anyMatch(w -> w.path("robot").asText().startsWith("triad/courier-")
                        && w.path("reason").asText().contains(" waits at ") && w.path("heldBy").size() > 0),
                        "one courier waited for the other, seen on /api/traffic: " + waits);
            }
            List<String> contacts = Files.readAllLines(buildingLog).stream().filter(l -> l.startsWith("contact ")).toList();
            assertEquals(List.of(), contacts, "no contact between the couriers in the building");
        } finally {
            if (building != null) {
                building.destroy();
                if (!building.waitFor(30, TimeUnit.SECONDS)) {
                    building.destroyForcibly().waitFor(30, TimeUnit.SECONDS);
                }
            }
        }
    }

    /** How often the door went from open (or moving) to CLOSED in these reported modes. */
    private static int closings(List<String> modes) {
        int n = 0;
        for (int i = 1; i < modes.size(); i++) {
            if (modes.get(i).equals(DeviceMessages.CLOSED) && !modes.get(i - 1).equals(DeviceMessages.CLOSED)) {
                n++;
            }
        }
        return n;
    }

    /** Waits (generously: the machine may be loaded) until the door reports CLOSED as its latest state. */
    private static void awaitClosed(Map<String, List<String>> modes, String door, Path buildingLog) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (true) {
            List<String> m = modes.getOrDefault(door, List.of());
            if (!m.isEmpty() && m.get(m.size() - 1).equals(DeviceMessages.CLOSED)) {
                return;
            }
            assertTrue(System.nanoTime() < deadline, door + " was not closed once nobody needed it: " + modes + "\n" + Files.readString(buildingLog));
            Thread.sleep(50);
        }
    }

    private static long submit(TriadService s, String room) {
        return s.fleet().submit(JSON.createObjectNode().put("task", "GoTo").set("args", JSON.createObjectNode().put("dst", room))).id();
    }

    private static TaskView awaitEnd(TriadService s, long id, long other) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(180);
        while (true) {
            TaskView t = s.fleet().task(id).orElseThrow();
            if (Set.of("completed", "aborted", "refused").contains(t.state())) {
                return t;
            }
            assertTrue(System.nanoTime() < deadline, "task " + id + " did not end: " + t + "\nthe other: " + s.fleet().task(other).orElseThrow());
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
