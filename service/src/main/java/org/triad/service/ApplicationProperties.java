package org.triad.service;

import java.io.IOException;
import java.io.InputStream;
import java.net.URL;
import java.util.Optional;
import java.util.Properties;

/**
 * The application's {@code META-INF/triad/application.properties} on a class loader, read once for each setting that
 * lives there (the charging policy, the dispatch limit); a file that cannot be read is a start-up error naming it.
 *
 * @param values the properties
 * @param where  the file's URL, for the error messages of a malformed setting
 */
record ApplicationProperties(Properties values, String where) {
    static final String RESOURCE = "META-INF/triad/application.properties";

    static Optional<ApplicationProperties> read(ClassLoader loader) {
        URL url = loader == null ? null : loader.getResource(RESOURCE);
        if (url == null) {
            return Optional.empty();
        }
        Properties p = new Properties();
        try (InputStream in = url.openStream()) {
            p.load(in);
        } catch (IOException e) {
            throw ServiceError.startup("cannot read " + url + ": " + e.getMessage());
        }
        return Optional.of(new ApplicationProperties(p, url.toString()));
    }
}
