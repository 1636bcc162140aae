package org.triad.pddl4j;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URL;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The repackaged PDDL4J must not bring back its bundled log4j 2.11 (Log4Shell range). */
class Log4jVersionIT {
    private static String location(Class<?> c) {
        return c.getProtectionDomain().getCodeSource().getLocation().toString();
    }

    @Test
    void pddl4jClassesComeFromTheRepackagedJar() throws Exception {
        String ff = location(Class.forName("fr.uga.pddl4j.planners.statespace.ff.FF"));
        assertTrue(ff.contains("triad-pddl4j"), ff);
        assertFalse(ff.contains("pddl4j-3.8.3.jar"), ff);
    }

    @Test
    void log4jCoreClassesComeFromACurrentLog4jJarOnly() throws Exception {
        for (String name : List.of("org.apache.logging.log4j.core.lookup.JndiLookup", "org.apache.logging.log4j.core.LoggerContext",
                "org.apache.logging.log4j.LogManager")) {
            Class<?> c = Class.forName(name);
            String where = location(c);
            assertTrue(where.matches(".*log4j-(core|api)-2\\.[0-9.]+\\.jar"), name + " loaded from " + where);
            String path = name.replace('.', '/') + ".class";
            List<URL> copies = Collections.list(getClass().getClassLoader().getResources(path));
            assertEquals(1, copies.size(), "copies of " + path + ": " + copies);
        }
        Package core = Class.forName("org.apache.logging.log4j.core.LoggerContext").getPackage();
        String version = core.getImplementationVersion();
        assertNotNull(version, "log4j-core has no Implementation-Version");
        assertTrue(atLeast(version, 2, 17), "log4j-core " + version + " is older than 2.17");
    }

    @Test
    void noBundledLog4jConfigurationIsVisible() throws Exception {
        List<URL> configs = new ArrayList<>(Collections.list(getClass().getClassLoader().getResources("log4j2.xml")));
        configs.removeIf(u -> !u.toString().contains("triad-pddl4j"));
        assertEquals(List.of(), configs);
    }

    static boolean atLeast(String version, int major, int minor) {
        String[] parts = version.split("[.-]");
        int ma = Integer.parseInt(parts[0]);
        int mi = Integer.parseInt(parts[1]);
        return ma > major || (ma == major && mi >= minor);
    }
}
