package org.triad.examples.hospital.vda5050;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.triad.runtime.app.LauncherWatch;
import org.triad.vda5050.broker.MosquittoBroker;
import org.triad.vda5050.mqtt.MqttLink;
import org.triad.vda5050.protocol.Connection;
import org.triad.vda5050.protocol.Messages.ConnectionState;
import org.triad.vda5050.protocol.Topic;

/**
 * A simulated robot started by a launcher (as {@code ./triad robot} starts it) notices when its launcher
 * was killed with SIGKILL, reports OFFLINE and ends, instead of staying online with nobody to stop it.
 */
class RobotLifetimeTest {
    @Test
    void aRobotWhoseLauncherIsKilledHardReportsOfflineAndEnds() throws Exception {
        Path dir = Path.of("target", "vda5050", "RobotLifetimeTest").toAbsolutePath();
        Files.createDirectories(dir);
        Path log = dir.resolve("courier-7.log");
        Files.deleteIfExists(log); // a previous run's 'ONLINE' must not count
        List<ConnectionState> seen = new CopyOnWriteArrayList<>();
        try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"));
                MqttLink watcher = MqttLink.connect(broker.url(), "lifetime-watcher", null, line -> { }, 10, 5)) {
            watcher.subscribe(Topic.CONNECTION.of("triad", "courier-7"), r -> seen.add(r.as(Connection.class).connectionState()));
            String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
            // the launcher: a shell that starts the robot with its own pid and stays its parent ('; true' keeps it from exec'ing java)
            String script = "'" + java + "' -Xmx256m -D" + LauncherWatch.PROPERTY + "=$$ -cp \"$CP\" " + HospitalAgvMain.class.getName()
                    + " --broker " + broker.url() + " --serial courier-7 --speed 10 > '" + log + "' 2>&1; true";
            ProcessBuilder pb = new ProcessBuilder("sh", "-c", script);
            pb.environment().put("CP", System.getProperty("java.class.path"));
            Process launcher = pb.start();
            Optional<ProcessHandle> robot = Optional.empty();
            try {
                long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
                while (!(Files.exists(log) && Files.readString(log).contains("courier-7 ONLINE"))) {
                    assertTrue(launcher.isAlive() && System.nanoTime() < deadline, "robot did not come online: "
                            + (Files.exists(log) ? Files.readString(log) : "no log"));
                    Thread.sleep(50);
                }
                robot = launcher.toHandle().children().findFirst();
                assertTrue(robot.isPresent(), "the robot runs as the launcher's child");
                launcher.destroyForcibly().waitFor(10, TimeUnit.SECONDS); // SIGKILL: the launcher cannot stop its child
                robot.get().onExit().get(60, TimeUnit.SECONDS);
                assertFalse(robot.get().isAlive());
                deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
                while (!seen.subList(Math.max(0, seen.indexOf(ConnectionState.ONLINE)), seen.size()).contains(ConnectionState.OFFLINE)
                        && System.nanoTime() < deadline) {
                    Thread.sleep(50);
                }
                // the broker persists: a previous run's retained connection state may come first
                List<ConnectionState> sinceOnline = seen.subList(Math.max(0, seen.indexOf(ConnectionState.ONLINE)), seen.size());
                assertTrue(sinceOnline.contains(ConnectionState.OFFLINE), "reported OFFLINE, not left online or broken: " + seen);
                assertFalse(sinceOnline.contains(ConnectionState.CONNECTIONBROKEN), "disconnected cleanly: " + seen);
                assertTrue(Files.readString(log).contains("the launching process"), Files.readString(log));
            } finally {
                launcher.toHandle().descendants().forEach(ProcessHandle::destroyForcibly);
                robot.ifPresent(ProcessHandle::destroyForcibly);
                launcher.destroyForcibly();
            }
        }
    }
}
