package org.triad.vda5050.broker;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.TimeUnit;

/**
 * A real Eclipse Mosquitto broker (the Debian package {@code mosquitto}) as a child process, for scripts,
 * {@code ./triad broker} and tests: listening on 127.0.0.1 on a free port (or a given one), configured from
 * the config file kept in this module ({@code vda5050/mosquitto.conf}), persisting into its own folder so a
 * {@link #restart()} keeps sessions and queued QoS 1 messages. {@link #close()} stops it; a JVM shutdown
 * hook kills it if nobody did.
 */
public final class MosquittoBroker implements AutoCloseable {
    private final Path dir;
    private final int port;
    private Process process;
    private final Thread reaper;

    private MosquittoBroker(Path dir, int port) {
        this.dir = dir;
        this.port = port;
        this.reaper = new Thread(this::kill, "mosquitto-reaper-" + port);
        Runtime.getRuntime().addShutdownHook(reaper);
    }

    /** Starts a broker on a free loopback port, with its config, persistence and log under {@code dir}. */
    public static MosquittoBroker start(Path dir) {
        return start(dir, freePort());
    }

    /** Starts a broker on the given loopback port. */
    public static MosquittoBroker start(Path dir, int port) {
        Objects.requireNonNull(dir, "dir");
        if (port < 1 || port > 65535) {
            throw new IllegalArgumentException("a port is 1..65535, not " + port);
        }
        MosquittoBroker b = new MosquittoBroker(dir.toAbsolutePath(), port);
        try {
            b.launch();
        } catch (RuntimeException e) {
            b.close();
            throw e;
        }
        return b;
    }

    /** {@code tcp://127.0.0.1:PORT}. */
    public String url() {
        return "tcp://127.0.0.1:" + port;
    }

    public int port() {
        return port;
    }

    public Path dir() {
        return dir;
    }

    public Path log() {
        return dir.resolve("mosquitto.log");
    }

    public synchronized boolean isRunning() {
        return process != null && process.isAlive();
    }

    /** The broker's process id while it runs (for CPU accounting in benchmarks). */
    public synchronized long pid() {
        return process == null ? -1 : process.pid();
    }

    /** Stops the broker (SIGTERM: it saves its persistent state) and starts it again on the same port and folder. */
    public synchronized void restart() {
        stop();
        launch();
    }

    /** Stops the broker gracefully (it writes its persistence file), waiting up to 10 s. */
    public synchronized void stop() {
        if (process == null) {
            return;
        }
        process.destroy();
        try {
            if (!process.waitFor(10, TimeUnit.SECONDS)) {
                process.destroyForcibly().waitFor(5, TimeUnit.SECONDS);
            }
        } catch (InterruptedException e) {
            process.destroyForcibly();
            Thread.currentThread().interrupt();
        }
        process = null;
    }

    @Override
    public synchronized void close() {
        stop();
        try {
            Runtime.getRuntime().removeShutdownHook(reaper);
        } catch (IllegalStateException e) {
            // the JVM is shutting down; the hook is running
        }
    }

    private synchronized void kill() {
        if (process != null) {
            process.destroyForcibly();
        }
    }

    private synchronized void launch() {
        String executable = executable();
        try {
            Files.createDirectories(dir);
            Path conf = dir.resolve("mosquitto.conf");
            Files.writeString(conf, config().replace("${port}", Integer.toString(port)).replace("${dir}", dir.toString())
                    .replace("${user}", System.getProperty("user.name")));
            process = new ProcessBuilder(List.of(executable, "-c", conf.toString()))
                    .redirectErrorStream(true)
                    .redirectOutput(dir.resolve("mosquitto.out").toFile())
                    .start();
        } catch (IOException e) {
            throw new UncheckedIOException("cannot start mosquitto in " + dir + ": " + e.getMessage(), e);
        }
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (System.nanoTime() < deadline) {
            if (!process.isAlive()) {
                throw new IllegalStateException("mosquitto exited at start-up (port " + port + "): " + tail());
            }
            try (Socket s = new Socket()) {
                s.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 200);
                return;
            } catch (IOException e) {
                sleep(50);
            }
        }
        kill();
        throw new IllegalStateException("mosquitto did not listen on 127.0.0.1:" + port + " within 10 s: " + tail());
    }

    private String tail() {
        for (Path p : List.of(log(), dir.resolve("mosquitto.out"))) {
            try {
                if (Files.exists(p) && Files.size(p) > 0) {
                    List<String> lines = Files.readAllLines(p);
                    return String.join(" | ", lines.subList(Math.max(0, lines.size() - 3), lines.size()));
                }
            } catch (IOException e) {
                // try the next
            }
        }
        return "no output";
    }

    private static String executable() {
        for (String d : System.getenv().getOrDefault("PATH", "/usr/bin:/usr/sbin").split(java.io.File.pathSeparator)) {
            if (Files.isExecutable(Path.of(d, "mosquitto"))) {
                return Path.of(d, "mosquitto").toString();
            }
        }
        for (String d : List.of("/usr/sbin", "/usr/local/sbin")) {
            if (Files.isExecutable(Path.of(d, "mosquitto"))) {
                return Path.of(d, "mosquitto").toString();
            }
        }
        throw new IllegalStateException("mosquitto is not installed (Debian: apt-get install mosquitto)");
    }

    private static String config() {
        try (InputStream in = MosquittoBroker.class.getResourceAsStream("/vda5050/mosquitto.conf")) {
            if (in == null) {
                throw new IllegalStateException("vda5050/mosquitto.conf is missing from the class path");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** A TCP port nobody listens on right now on 127.0.0.1. */
    public static int freePort() {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            s.setReuseAddress(true);
            return s.getLocalPort();
        } catch (IOException e) {
            throw new UncheckedIOException("no free port on 127.0.0.1", e);
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
