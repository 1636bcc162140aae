package org.triad.examples.hospital.vda5050;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * A simulated courier in its own JVM ({@link HospitalAgvMain} on this test's class path), so tests can kill it
 * hard (the broker then publishes its last will) or freeze it (SIGSTOP: it stops sending state). Always ended
 * by {@link #close()}, also when the test fails.
 */
final class AgvProcess implements AutoCloseable {
    private final Process process;
    private final Path output;

    private AgvProcess(Process process, Path output) {
        this.process = process;
        this.output = output;
    }

    /**
     * A route from where the courier parked in the lobby (the dock or a spot: the node its AGV reports, a node of the
     * hospital's traffic map) out through the lobby's waypoint and on along {@code then}.
     */
    static java.util.List<String> outOfTheLobby(org.triad.vda5050.master.RemoteAgv agv, String... then) {
        java.util.List<String> route = new java.util.ArrayList<>();
        route.add(agv.state().orElseThrow().lastNodeId());
        route.add(org.triad.examples.hospital.LobbyParking.HALL);
        route.addAll(java.util.List.of(then));
        return route;
    }

    static AgvProcess start(String broker, String serial, double speed, Path dir, String... extra) {
        List<String> args = new ArrayList<>(List.of("--broker", broker, "--serial", serial, "--speed", Double.toString(speed)));
        args.addAll(List.of(extra));
        return launch(args, dir.resolve(serial + ".log"), serial + " ONLINE");
    }

    /** One building with {@code count} couriers (courier-1 .. courier-N) in one JVM, once all are online. */
    static AgvProcess building(String broker, int count, double speed, Path dir, String... extra) {
        List<String> args = new ArrayList<>(List.of("--broker", broker, "--count", Integer.toString(count), "--speed", Double.toString(speed)));
        args.addAll(List.of(extra));
        return launch(args, dir.resolve("building.log"), "building: one hospital");
    }

    private static AgvProcess launch(List<String> args, Path out, String ready) {
        try {
            Files.createDirectories(out.getParent());
            List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx256m", "-cp",
                    System.getProperty("java.class.path"), HospitalAgvMain.class.getName()));
            cmd.addAll(args);
            Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(out.toFile()).start();
            AgvProcess agv = new AgvProcess(p, out);
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (!agv.output().contains(ready)) {
                if (!p.isAlive() || System.nanoTime() > deadline) {
                    agv.close();
                    throw new IllegalStateException("no '" + ready + "' from the robots' process: " + agv.output());
                }
                Thread.sleep(50);
            }
            return agv;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException(e);
        }
    }

    /** Everything the robot printed so far. */
    String output() {
        try {
            return Files.exists(output) ? Files.readString(output) : "";
        } catch (IOException e) {
            return "";
        }
    }

    /** The lines the robot printed that contain {@code text}. */
    List<String> lines(String text) {
        return output().lines().filter(l -> l.contains(text)).toList();
    }

    /** SIGTERM, and waits for the process to end (it reports OFFLINE and prints how fast its building ran). */
    void stop() {
        process.destroy();
        try {
            process.waitFor(30, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** SIGKILL: the process dies without a word, the broker publishes its last will. */
    void kill() {
        process.destroyForcibly();
        try {
            process.waitFor(10, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** SIGSTOP: the process stays connected as far as TCP goes but sends nothing. */
    void freeze() {
        signal("STOP");
    }

    private void signal(String name) {
        try {
            new ProcessBuilder("kill", "-" + name, Long.toString(process.pid())).inheritIO().start().waitFor(5, TimeUnit.SECONDS);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    @Override
    public void close() {
        if (process.isAlive()) {
            signal("CONT");
            kill();
        }
    }
}
