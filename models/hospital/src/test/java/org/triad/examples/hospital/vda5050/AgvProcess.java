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

    static AgvProcess start(String broker, String serial, double speed, Path dir, String... extra) {
        try {
            Files.createDirectories(dir);
            Path out = dir.resolve(serial + ".log");
            List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx256m", "-cp",
                    System.getProperty("java.class.path"), HospitalAgvMain.class.getName(), "--broker", broker, "--serial", serial, "--speed",
                    Double.toString(speed)));
            cmd.addAll(List.of(extra));
            Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(out.toFile()).start();
            AgvProcess agv = new AgvProcess(p, out);
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            while (!agv.output().contains(serial + " ONLINE")) {
                if (!p.isAlive() || System.nanoTime() > deadline) {
                    agv.close();
                    throw new IllegalStateException("robot " + serial + " did not come online: " + agv.output());
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
