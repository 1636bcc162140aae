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

import org.triad.vda5050.security.BrokerCredentials;

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
    private final BrokerCredentials credentials;
    private Process process;
    private final Thread reaper;

    private MosquittoBroker(Path dir, int port, BrokerCredentials credentials) {
        this.dir = dir;
        this.port = port;
        this.credentials = credentials;
        this.reaper = new Thread(this::kill, "mosquitto-reaper-" + port);
        Runtime.getRuntime().addShutdownHook(reaper);
    }

    /** Starts a broker on a free loopback port, with its config, persistence and log under {@code dir}. */
    public static MosquittoBroker start(Path dir) {
        return start(dir, freePort());
    }

    /** Starts a broker on the given loopback port: plain TCP, anonymous clients (tests and benchmarks on one machine). */
    public static MosquittoBroker start(Path dir, int port) {
        return start(dir, port, null);
    }

    /**
     * Starts a secured broker on the given loopback port: TLS with client certificates, a password per identity
     * and the access control list of {@code credentials} (see {@link BrokerCredentials}); anonymous clients
     * are refused. Its address is {@code ssl://127.0.0.1:PORT}.
     */
    public static MosquittoBroker startSecured(Path dir, int port, BrokerCredentials credentials) {
        return start(dir, port, Objects.requireNonNull(credentials, "credentials"));
    }

    private static MosquittoBroker start(Path dir, int port, BrokerCredentials credentials) {
        Objects.requireNonNull(dir, "dir");
        if (port < 1 || port > 65535) {
            throw new IllegalArgumentException("a port is 1..65535, not " + port);
        }
        MosquittoBroker b = new MosquittoBroker(dir.toAbsolutePath(), port, credentials);
        try {
            b.launch();
        } catch (RuntimeException e) {
            b.close();
            throw e;
        }
        return b;
    }

    /** {@code tcp://127.0.0.1:PORT}, or {@code ssl://127.0.0.1:PORT} when it is secured. */
    public String url() {
        return (credentials != null ? "ssl" : "tcp") + "://127.0.0.1:" + port;
    }

    /** The credentials folder of a secured broker, or null for a plain one. */
    public BrokerCredentials credentials() {
        return credentials;
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
            String text = config(credentials != null ? "/vda5050/mosquitto-secured.conf" : "/vda5050/mosquitto.conf")
                    .replace("${port}", Integer.toString(port)).replace("${dir}", dir.toString())
                    .replace("${user}", System.getProperty("user.name"));
            if (credentials != null) {
                text = text.replace("${credentials}", credentials.dir().toString());
            }
            Files.writeString(conf, text);
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
            } catch (IOException e) {
                sleep(50);
                continue;
            }
            // Mosquitto listens before it loads its certificates: one it cannot load ends it right after
            try {
                if (credentials != null && process.waitFor(300, TimeUnit.MILLISECONDS)) {
                    throw new IllegalStateException("mosquitto exited at start-up (port " + port + "): " + tail());
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            return;
        }
        kill();
        throw new IllegalStateException("mosquitto did not listen on 127.0.0.1:" + port + " within 10 s: " + tail());
    }

    private String tail() {
        for (Path p : List.of(log(), dir.resolve("mosquitto.out"))) {
            try {
                if (Files.exists(p) && Files.size(p) > 0) {
                    List<String> lines = Files.readAllLines(p);
                    for (String l : lines) {
                        if (l.contains(": Error: ")) {
                            return l.substring(l.indexOf("Error: "));
                        }
                    }
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

    private static String config(String resource) {
        try (InputStream in = MosquittoBroker.class.getResourceAsStream(resource)) {
            if (in == null) {
                throw new IllegalStateException(resource + " is missing from the class path");
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
