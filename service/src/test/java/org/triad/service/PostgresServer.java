package org.triad.service;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

/**
 * A PostgreSQL server of the test's own (Debian's {@code postgresql} package): initdb into a fresh
 * folder, a free port on 127.0.0.1, stopped and deleted at the end. As root, the server runs as the
 * {@code postgres} user (it refuses to run as root).
 */
final class PostgresServer implements AutoCloseable {
    private final Path bin;
    private final Path data;
    private final int port;
    private final boolean asPostgres;

    private PostgresServer(Path bin, Path data, int port, boolean asPostgres) {
        this.bin = bin;
        this.data = data;
        this.port = port;
        this.asPostgres = asPostgres;
    }

    static PostgresServer start() throws IOException, InterruptedException {
        Path bin = binaries();
        boolean root = "root".equals(System.getProperty("user.name"));
        Path folder = Files.createTempDirectory("triad-pg");
        Path data = folder.resolve("data");
        if (root) {
            run(List.of("chown", "postgres:postgres", folder.toString()), false);
        }
        int port;
        try (ServerSocket s = new ServerSocket(0)) {
            port = s.getLocalPort();
        }
        PostgresServer server = new PostgresServer(bin, data, port, root);
        server.pg(List.of(bin.resolve("initdb").toString(), "-D", data.toString(), "-U", "triad", "-A", "trust", "--no-sync", "-E", "UTF8"));
        server.pg(List.of(bin.resolve("pg_ctl").toString(), "-D", data.toString(), "-w", "-t", "60", "-l", folder.resolve("log").toString(),
                "-o", "-p " + port + " -h 127.0.0.1 -k " + folder + " -c fsync=on", "start"));
        server.pg(List.of(bin.resolve("createdb").toString(), "-h", "127.0.0.1", "-p", String.valueOf(port), "-U", "triad", "triad"));
        return server;
    }

    /** Stops the server as a crash would (every connection is cut) and starts it again after {@code downMillis}. */
    void crashAndRestart(long downMillis) throws IOException, InterruptedException {
        pg(List.of(bin.resolve("pg_ctl").toString(), "-D", data.toString(), "-m", "immediate", "-w", "stop"));
        Thread.sleep(downMillis);
        Path folder = data.getParent();
        pg(List.of(bin.resolve("pg_ctl").toString(), "-D", data.toString(), "-w", "-t", "60", "-l", folder.resolve("log").toString(),
                "-o", "-p " + port + " -h 127.0.0.1 -k " + folder + " -c fsync=on", "start"));
    }

    /** {@code postgresql://triad@127.0.0.1:PORT/triad} */
    String url() {
        return "postgresql://triad@127.0.0.1:" + port + "/triad";
    }

    private static Path binaries() {
        try (Stream<Path> versions = Files.list(Path.of("/usr/lib/postgresql"))) {
            return versions.map(v -> v.resolve("bin")).filter(b -> Files.isExecutable(b.resolve("initdb")))
                    .max(Comparator.comparing(b -> Integer.parseInt(b.getParent().getFileName().toString().replaceAll("\\D", "0"))))
                    .orElseThrow(() -> new IllegalStateException("no /usr/lib/postgresql/*/bin/initdb: install Debian's postgresql package"));
        } catch (IOException e) {
            throw new IllegalStateException("no /usr/lib/postgresql: install Debian's postgresql package", e);
        }
    }

    private void pg(List<String> command) throws IOException, InterruptedException {
        List<String> c = new ArrayList<>();
        if (asPostgres) {
            c.addAll(List.of("runuser", "-u", "postgres", "--"));
        }
        c.addAll(command);
        run(c, true);
    }

    private static void run(List<String> command, boolean check) throws IOException, InterruptedException {
        Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        if (!p.waitFor(120, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            throw new IllegalStateException(command + " did not end in 120 s: " + out);
        }
        if (check && p.exitValue() != 0) {
            throw new IllegalStateException(command + " failed (" + p.exitValue() + "): " + out);
        }
    }

    @Override
    public void close() {
        try {
            pg(List.of(bin.resolve("pg_ctl").toString(), "-D", data.toString(), "-m", "immediate", "-w", "stop"));
        } catch (IOException | InterruptedException | RuntimeException e) {
            // deleting the folder below ends nothing, but the test's result matters more
        }
        try (Stream<Path> all = Files.walk(data.getParent())) {
            all.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
