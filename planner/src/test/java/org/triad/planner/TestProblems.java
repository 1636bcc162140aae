package org.triad.planner;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.HashMap;
import java.util.Map;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

/** Loads the small benchmark copies under src/test/resources/pddl. */
public final class TestProblems {
    private TestProblems() { }

    public static String text(String path) {
        try (InputStream in = TestProblems.class.getResourceAsStream("/pddl/" + path)) {
            if (in == null) throw new IllegalArgumentException("missing test resource pddl/" + path);
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    public static Domain domain(String path) {
        return PddlParser.parseDomain(text(path), path);
    }

    public static Problem problem(String path) {
        return PddlParser.parseProblem(text(path), path);
    }

    /** Optimal plan lengths of the hospital problems, keyed like {@code p-10-a}. */
    public static Map<String, Integer> hospitalOptimal() {
        Map<String, Integer> out = new HashMap<>();
        for (String line : text("hospital/optimal.tsv").split("\\R")) {
            String[] c = line.split("\t");
            if (c.length < 7 || c[0].equals("N")) continue;
            out.put("p-" + c[0] + "-" + c[5], Integer.parseInt(c[6]));
        }
        return out;
    }
}
