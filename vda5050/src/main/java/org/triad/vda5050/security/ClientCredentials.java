package org.triad.vda5050.security;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import java.util.Optional;

import javax.net.ssl.KeyManagerFactory;
import javax.net.ssl.SSLContext;
import javax.net.ssl.SSLSocketFactory;
import javax.net.ssl.TrustManagerFactory;

/**
 * What one MQTT client logs in to a secured broker with: its identity (the MQTT user name), its password,
 * its client certificate and key, and the CA that signed the broker's certificate. Read from a folder made
 * by {@code ./triad broker} ({@link BrokerCredentials}); the folder is named by {@code --credentials DIR}
 * on the command line, the system property {@value #PROPERTY} or the environment variable {@value #ENVIRONMENT}.
 */
public final class ClientCredentials {
    /** The system property naming the credentials folder. */
    public static final String PROPERTY = "triad.mqtt.credentials";
    /** The environment variable naming the credentials folder (when the property is not set). */
    public static final String ENVIRONMENT = "TRIAD_MQTT_CREDENTIALS";

    private final String identity;
    private final char[] password;
    private final Path keyStore;
    private final Path caCertificate;

    private ClientCredentials(String identity, char[] password, Path keyStore, Path caCertificate) {
        this.identity = identity;
        this.password = password;
        this.keyStore = keyStore;
        this.caCertificate = caCertificate;
    }

    /** The credentials folder named by {@value #PROPERTY} or {@value #ENVIRONMENT}, if any. */
    public static Optional<Path> configuredFolder() {
        String p = System.getProperty(PROPERTY);
        if (p == null || p.isBlank()) {
            p = System.getenv(ENVIRONMENT);
        }
        return p == null || p.isBlank() ? Optional.empty() : Optional.of(Path.of(p));
    }

    /**
     * The credentials {@code identity} logs in to the secured broker {@code broker} with, from the configured folder
     * ({@link #configuredFolder()}).
     *
     * @throws IllegalArgumentException without an identity, without a configured folder, or when the identity's files are missing
     */
    public static ClientCredentials forBroker(String broker, String identity) {
        if (identity == null) {
            throw new IllegalArgumentException("the secured broker " + broker + " needs the client's identity");
        }
        Path dir = configuredFolder().orElseThrow(() -> new IllegalArgumentException("the secured broker " + broker
                + " needs credentials: --credentials DIR, or " + ENVIRONMENT + "=DIR (the folder ./triad broker made)"));
        return load(dir, identity);
    }

    /**
     * Reads {@code identity}'s credentials from the folder.
     *
     * @throws IllegalArgumentException naming the missing file and how to make it
     */
    public static ClientCredentials load(Path dir, String identity) {
        BrokerCredentials.checkIdentity(identity, "client identity");
        Path pw = BrokerCredentials.password(dir, identity);
        Path ks = BrokerCredentials.keyStore(dir, identity);
        Path ca = dir.resolve("ca.crt");
        for (Path p : new Path[] { ca, pw, ks }) {
            if (!Files.isReadable(p)) {
                throw new IllegalArgumentException("no credentials for '" + identity + "' in " + dir.toAbsolutePath() + ": " + p.getFileName()
                        + " is missing (./triad broker --credentials " + dir
                        + (BrokerCredentials.MASTER.equals(identity) || BrokerCredentials.BUILDING.equals(identity) ? "" : " --robots " + identity)
                        + " makes them)");
            }
        }
        return new ClientCredentials(identity, readPassword(pw).toCharArray(), ks, ca);
    }

    public String identity() {
        return identity;
    }

    /** The MQTT password (a copy). */
    public char[] password() {
        return password.clone();
    }

    /** TLS sockets that present this client's certificate and trust only the broker's CA. */
    public SSLSocketFactory socketFactory() {
        try {
            KeyStore keys = KeyStore.getInstance("PKCS12");
            try (InputStream in = Files.newInputStream(keyStore)) {
                keys.load(in, password);
            }
            KeyManagerFactory kmf = KeyManagerFactory.getInstance(KeyManagerFactory.getDefaultAlgorithm());
            kmf.init(keys, password);
            KeyStore trust = KeyStore.getInstance("PKCS12");
            trust.load(null, null);
            trust.setCertificateEntry("triad-broker-ca", Certificates.readCertificate(caCertificate));
            TrustManagerFactory tmf = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm());
            tmf.init(trust);
            SSLContext tls = SSLContext.getInstance("TLS");
            tls.init(kmf.getKeyManagers(), tmf.getTrustManagers(), null);
            return tls.getSocketFactory();
        } catch (IOException | GeneralSecurityException e) {
            throw new IllegalArgumentException("cannot use the credentials of '" + identity + "' (" + keyStore + "): " + e.getMessage(), e);
        }
    }

    static String readPassword(Path file) {
        try {
            return Files.readString(file, StandardCharsets.UTF_8).trim();
        } catch (IOException e) {
            throw new IllegalArgumentException("cannot read " + file + ": " + e.getMessage(), e);
        }
    }
}
