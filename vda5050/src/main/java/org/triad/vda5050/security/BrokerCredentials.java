package org.triad.vda5050.security;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import java.security.SecureRandom;
import java.security.cert.Certificate;
import java.util.ArrayList;
import java.util.Base64;
import java.util.Collection;
import java.util.List;
import java.util.Objects;
import java.util.TreeSet;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * The folder of a secured broker's credentials, made by {@code ./triad broker} once and extended (never
 * replaced) when identities are added:
 *
 * <pre>
 * ca.crt, ca.key            the certificate authority (keep ca.key private: it can issue identities)
 * server.crt, server.key    the broker's TLS certificate (names localhost and 127.0.0.1)
 * passwd                    Mosquitto's password file (PBKDF2-SHA512 hashes, made by mosquitto_passwd)
 * acl                       Mosquitto's access control list, written from the identities
 * clients/NAME.p12          NAME's client certificate and key (PKCS#12, protected by NAME's password)
 * clients/NAME.password     NAME's MQTT password
 * </pre>
 *
 * The identity {@value #MASTER} is master control, {@value #BUILDING} the building serving its doors and lifts;
 * every other identity is a robot whose serial number is its name. A robot needs only {@code ca.crt} and its own two files under {@code clients/}. Secret files are
 * mode 0600 and the folder 0700.
 */
public final class BrokerCredentials {
    /** Master control's identity. */
    public static final String MASTER = "master";
    /** The building's identity: it serves the doors and lifts (device protocol) and nobody else may. */
    public static final String BUILDING = "building";

    private static final Pattern IDENTITY = Pattern.compile("[A-Za-z0-9][A-Za-z0-9._-]{0,63}");
    private static final SecureRandom RANDOM = new SecureRandom();

    private final Path dir;
    private final List<String> made;

    private BrokerCredentials(Path dir, List<String> made) {
        this.dir = dir;
        this.made = List.copyOf(made);
    }

    /**
     * Makes what is missing in {@code dir}: the CA and server certificate on first use, and an identity for
     * master control and for each robot not there yet; then writes the password file and the ACL for every
     * identity the folder holds. What exists is kept (robots keep their credentials).
     *
     * @param manufacturer the manufacturer in the robots' topics ({@code uagv/v2/MANUFACTURER/SERIAL/...})
     */
    public static BrokerCredentials ensure(Path dir, String manufacturer, Collection<String> robots) {
        Objects.requireNonNull(dir, "dir");
        checkIdentity(manufacturer, "manufacturer");
        for (String r : robots) {
            checkIdentity(r, "robot serial number");
            if (r.equals(MASTER)) {
                throw new IllegalArgumentException("'" + MASTER + "' is master control's identity, not a robot's serial number");
            }
            if (r.equals(BUILDING)) {
                throw new IllegalArgumentException("'" + BUILDING + "' is the building's identity (its doors and lifts), not a robot's serial number");
            }
        }
        Path d = dir.toAbsolutePath();
        SecretFiles.privateFolder(d);
        SecretFiles.privateFolder(d.resolve("clients"));
        List<String> made = new ArrayList<>();
        Certificates.Issued ca;
        if (Files.exists(d.resolve("ca.crt")) && Files.exists(d.resolve("ca.key"))) {
            ca = new Certificates.Issued(Certificates.readKey(d.resolve("ca.key")), Certificates.readCertificate(d.resolve("ca.crt")));
        } else {
            ca = Certificates.newCa("Triad broker CA " + d.getFileName());
            Certificates.writePem(d.resolve("ca.key"), ca.key());
            Certificates.writePem(d.resolve("ca.crt"), ca.certificate());
            made.add("ca");
        }
        if (!Files.exists(d.resolve("server.crt")) || !Files.exists(d.resolve("server.key"))) {
            Certificates.Issued server = Certificates.newServer(ca, List.of("localhost"), List.of("127.0.0.1"));
            Certificates.writePem(d.resolve("server.key"), server.key());
            Certificates.writePem(d.resolve("server.crt"), server.certificate());
            made.add("server");
        }
        List<String> wanted = new ArrayList<>();
        wanted.add(MASTER);
        wanted.add(BUILDING);
        wanted.addAll(robots);
        for (String identity : wanted) {
            if (!Files.exists(password(d, identity)) || !Files.exists(keyStore(d, identity))) {
                issue(d, ca, identity);
                made.add(identity);
            }
        }
        BrokerCredentials c = new BrokerCredentials(d, made);
        c.writeAccessFiles(manufacturer);
        return c;
    }

    /** The folder. */
    public Path dir() {
        return dir;
    }

    /** What {@link #ensure} made now ({@code ca}, {@code server}, identities), empty if everything existed. */
    public List<String> made() {
        return made;
    }

    /** Every identity the folder holds, sorted. */
    public List<String> identities() {
        try (Stream<Path> s = Files.list(dir.resolve("clients"))) {
            TreeSet<String> names = new TreeSet<>();
            s.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".password"))
                    .forEach(n -> names.add(n.substring(0, n.length() - ".password".length())));
            return List.copyOf(names);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot list " + dir.resolve("clients") + ": " + e.getMessage(), e);
        }
    }

    public Path caCertificate() {
        return dir.resolve("ca.crt");
    }

    public Path serverCertificate() {
        return dir.resolve("server.crt");
    }

    public Path serverKey() {
        return dir.resolve("server.key");
    }

    public Path passwordFile() {
        return dir.resolve("passwd");
    }

    public Path aclFile() {
        return dir.resolve("acl");
    }

    /** The credentials one client logs in with. */
    public ClientCredentials client(String identity) {
        return ClientCredentials.load(dir, identity);
    }

    static Path password(Path dir, String identity) {
        return dir.resolve("clients").resolve(identity + ".password");
    }

    static Path keyStore(Path dir, String identity) {
        return dir.resolve("clients").resolve(identity + ".p12");
    }

    static void checkIdentity(String name, String what) {
        if (name == null || !IDENTITY.matcher(name).matches()) {
            throw new IllegalArgumentException("a " + what + " is 1..64 letters, digits, '.', '_' or '-' (starting with a letter or"
                    + " digit), not '" + name + "'");
        }
    }

    private static void issue(Path dir, Certificates.Issued ca, String identity) {
        byte[] secret = new byte[24];
        RANDOM.nextBytes(secret);
        String pw = Base64.getUrlEncoder().withoutPadding().encodeToString(secret);
        Certificates.Issued client = Certificates.newClient(ca, identity);
        try {
            KeyStore ks = KeyStore.getInstance("PKCS12");
            ks.load(null, null);
            ks.setKeyEntry(identity, client.key(), pw.toCharArray(), new Certificate[] { client.certificate(), ca.certificate() });
            var bytes = new java.io.ByteArrayOutputStream();
            ks.store(bytes, pw.toCharArray());
            SecretFiles.write(keyStore(dir, identity), bytes.toByteArray());
        } catch (IOException | GeneralSecurityException e) {
            throw new IllegalStateException("cannot store the key of '" + identity + "': " + e.getMessage(), e);
        }
        // the password last: an identity counts as made only when both files exist
        SecretFiles.write(password(dir, identity), pw + "\n");
    }

    private void writeAccessFiles(String manufacturer) {
        List<String> ids = identities();
        StringBuilder plain = new StringBuilder();
        for (String id : ids) {
            plain.append(id).append(':').append(ClientCredentials.readPassword(password(dir, id))).append('\n');
        }
        SecretFiles.write(passwordFile(), plain.toString());
        hashPasswords(passwordFile());
        SecretFiles.write(aclFile(), AccessControlList.of(manufacturer,
                ids.stream().filter(i -> !i.equals(MASTER) && !i.equals(BUILDING)).toList()));
    }

    /** Mosquitto's own tool hashes the file in place, in the format the installed broker reads. */
    private static void hashPasswords(Path file) {
        String tool = Executables.find("mosquitto_passwd");
        try {
            Process p = new ProcessBuilder(tool, "-U", file.toString()).redirectErrorStream(true).start();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
            if (!p.waitFor(30, TimeUnit.SECONDS) || p.exitValue() != 0) {
                p.destroyForcibly();
                Files.deleteIfExists(file);
                throw new IllegalStateException("mosquitto_passwd could not hash " + file + ": " + out);
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot run mosquitto_passwd: " + e.getMessage(), e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while hashing passwords", e);
        }
    }
}
