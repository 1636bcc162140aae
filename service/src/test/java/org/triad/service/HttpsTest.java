package org.triad.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.KeyStore;
import java.time.Duration;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import javax.net.ssl.SSLContext;
import javax.net.ssl.TrustManagerFactory;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Given a certificate, the service speaks HTTPS only; a key store it cannot use stops the start with one line. */
class HttpsTest {
    private static final String PASSWORD = "keystore-password";
    @TempDir
    static Path shared;
    private static Path ks;

    @org.junit.jupiter.api.BeforeAll
    static void makeKeyStore() throws Exception {
        ks = keyStore(shared);
    }

    /** A self-signed certificate for localhost and 127.0.0.1, made by the JDK's keytool. */
    private static Path keyStore(Path dir) throws Exception {
        Path ks = dir.resolve("service.p12");
        Process p = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "keytool").toString(), "-genkeypair", "-alias", "triad",
                "-keyalg", "EC", "-groupname", "secp256r1", "-dname", "CN=localhost", "-ext", "SAN=dns:localhost,ip:127.0.0.1", "-validity", "2",
                "-storetype", "PKCS12", "-keystore", ks.toString(), "-storepass", PASSWORD, "-keypass", PASSWORD).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes());
        assertTrue(p.waitFor(60, TimeUnit.SECONDS) && p.exitValue() == 0, out);
        return ks;
    }

    private static TriadService.Options options(Path dir, Map<String, String> extra) {
        Map<String, String> env = new HashMap<>(Map.of(AccessTokens.SUBMIT_ENV, ServiceFixture.SUBMIT, AccessTokens.OPERATOR_ENV, ServiceFixture.OPERATOR));
        env.putAll(extra);
        return new TriadService.Options(ServiceFixture.HOSPITAL, List.of("dry:1"), null, dir.resolve("db"), null, "127.0.0.1", 0, env);
    }

    @Test
    void givenACertificateTheServiceSpeaksHttpsOnly(@TempDir Path dir) throws Exception {
        try (TriadService s = TriadService.start(options(dir, Map.of(HttpsSettings.KEYSTORE_ENV, ks.toString(), HttpsSettings.PASSWORD_ENV, PASSWORD)))) {
            assertTrue(s.url().startsWith("https://127.0.0.1:"), s.url());
            KeyStore trust = KeyStore.getInstance("PKCS12");
            try (InputStream in = Files.newInputStream(ks)) {
                trust.load(in, PASSWORD.toCharArray());
            }
            TrustManagerFactory tmf = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm());
            tmf.init(trust);
            SSLContext tls = SSLContext.getInstance("TLS");
            tls.init(null, tmf.getTrustManagers(), null);
            HttpClient client = HttpClient.newBuilder().sslContext(tls).connectTimeout(Duration.ofSeconds(10)).build();
            HttpResponse<String> r = client.send(HttpRequest.newBuilder(URI.create(s.url() + "/api/tasks"))
                    .header("Authorization", "Bearer " + ServiceFixture.SUBMIT).timeout(Duration.ofSeconds(30)).build(), HttpResponse.BodyHandlers.ofString());
            assertEquals(200, r.statusCode(), r.body());
            // plain HTTP on the same port is not served
            HttpClient plain = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(10)).build();
            String http = s.url().replace("https://", "http://");
            boolean refused;
            try {
                // Jetty waits for a TLS handshake that never comes: no answer within a few seconds counts as refused
                HttpResponse<String> p = plain.send(HttpRequest.newBuilder(URI.create(http + "/api/tasks")).timeout(Duration.ofSeconds(3))
                        .header("Authorization", "Bearer " + ServiceFixture.SUBMIT).build(), HttpResponse.BodyHandlers.ofString());
                refused = p.statusCode() == 400;
            } catch (java.io.IOException e) {
                refused = true;
            }
            assertTrue(refused, "plain HTTP got an answer from the HTTPS port");
        }
    }

    @Test
    void aKeyStoreThatCannotBeUsedIsOneLine(@TempDir Path dir) {
        ServiceError e = assertThrows(ServiceError.class,
                () -> TriadService.start(options(dir, Map.of(HttpsSettings.KEYSTORE_ENV, ks.toString(), HttpsSettings.PASSWORD_ENV, "wrong"))));
        assertTrue(e.getMessage().startsWith("HTTPS key store " + ks + " cannot be used (PKCS#12 with TRIAD_HTTPS_PASSWORD as its password)"),
                e.getMessage());
        assertEquals(1, e.getMessage().lines().count());
    }
}
