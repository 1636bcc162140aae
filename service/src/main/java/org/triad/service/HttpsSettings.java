package org.triad.service;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import java.util.Collections;
import java.util.Map;

import org.eclipse.jetty.server.Connector;
import org.eclipse.jetty.server.HttpConfiguration;
import org.eclipse.jetty.server.HttpConnectionFactory;
import org.eclipse.jetty.server.SecureRequestCustomizer;
import org.eclipse.jetty.server.Server;
import org.eclipse.jetty.server.ServerConnector;
import org.eclipse.jetty.server.SslConnectionFactory;
import org.eclipse.jetty.util.ssl.SslContextFactory;

/**
 * HTTPS when the service is given a certificate: a PKCS#12 key store (certificate chain and key) named by
 * {@value #KEYSTORE_ENV} and its password by {@value #PASSWORD_ENV} (from the environment, or set by
 * {@code ./triad serve --https-keystore FILE}). Then the service listens for HTTPS only.
 */
final class HttpsSettings {
    static final String KEYSTORE_ENV = "TRIAD_HTTPS_KEYSTORE";
    static final String PASSWORD_ENV = "TRIAD_HTTPS_PASSWORD";

    private final Path keyStore;
    private final String password;

    private HttpsSettings(Path keyStore, String password) {
        this.keyStore = keyStore;
        this.password = password;
    }

    /**
     * The settings the environment names, or null for plain HTTP.
     *
     * @throws ServiceError a start-up error naming the key store when it cannot be read with the password
     */
    static HttpsSettings from(Map<String, String> env) {
        String file = env.get(KEYSTORE_ENV);
        if (file == null || file.isBlank()) {
            return null;
        }
        Path p = Path.of(file);
        String pw = env.getOrDefault(PASSWORD_ENV, "");
        if (!Files.isReadable(p)) {
            throw ServiceError.startup("HTTPS key store " + p + " cannot be read");
        }
        try (InputStream in = Files.newInputStream(p)) {
            KeyStore ks = KeyStore.getInstance("PKCS12");
            ks.load(in, pw.toCharArray());
            if (Collections.list(ks.aliases()).stream().noneMatch(a -> isKey(ks, a))) {
                throw ServiceError.startup("HTTPS key store " + p + " holds no key and certificate");
            }
        } catch (IOException | GeneralSecurityException e) {
            throw ServiceError.startup("HTTPS key store " + p + " cannot be used (PKCS#12 with " + PASSWORD_ENV + " as its password): "
                    + e.getMessage());
        }
        return new HttpsSettings(p, pw);
    }

    private static boolean isKey(KeyStore ks, String alias) {
        try {
            return ks.isKeyEntry(alias);
        } catch (GeneralSecurityException e) {
            return false;
        }
    }

    /** Jetty's TLS connector on {@code host:port}. */
    Connector connector(Server server, HttpConfiguration http, String host, int port) {
        SslContextFactory.Server tls = new SslContextFactory.Server();
        tls.setKeyStorePath(keyStore.toAbsolutePath().toString());
        tls.setKeyStoreType("PKCS12");
        tls.setKeyStorePassword(password);
        HttpConfiguration https = new HttpConfiguration(http);
        // clients reach the service by address as often as by name: no SNI host check
        https.addCustomizer(new SecureRequestCustomizer(false));
        ServerConnector c = new ServerConnector(server, new SslConnectionFactory(tls, "http/1.1"), new HttpConnectionFactory(https));
        c.setHost(host);
        c.setPort(port);
        return c;
    }
}
