package org.triad.refarc;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.State;
import org.triad.runtime.component.Component;
import org.triad.runtime.component.ComposedComponent;
import org.triad.runtime.component.InPort;
import org.triad.runtime.component.OutPort;
import org.triad.runtime.component.Port;

/**
 * The Java components (generated from the .arc models in src/main/arc, extended by hand-written
 * behavior) have the ports, subcomponents and connectors their models declare, read independently
 * of the generator from the model text.
 */
class ArcModelConsistencyTest {
    private static final Path MODELS = Path.of("src/main/arc/org/triad/refarc");
    private static final Pattern PORT = Pattern.compile("^\\s*port (in|out) (\\w+) (\\w+);", Pattern.MULTILINE);
    private static final Pattern SUB = Pattern.compile("^\\s*([A-Z]\\w*) (\\w+)(\\([^)]*\\))?;", Pattern.MULTILINE);
    private static final Pattern CONNECTOR = Pattern.compile("^\\s*([\\w.]+) -> ([\\w., ]+);", Pattern.MULTILINE);

    private static final ActionRunner NO_ACTIONS = new ActionRunner() {
        @Override
        public Optional<String> violatedPrecondition(GroundAction a, State now) {
            return Optional.empty();
        }

        @Override
        public boolean execute(GroundAction a) {
            return true;
        }
    };

    @Test
    void refArcMatchesItsModel() throws IOException {
        assertMatches("RefArc.arc", new RefArc(() -> null, (g, s) -> null, NO_ACTIONS));
    }

    @Test
    void openRefArcMatchesItsModel() throws IOException {
        assertMatches("OpenRefArc.arc", new OpenRefArc(() -> null, (g, s) -> null, NO_ACTIONS));
    }

    @Test
    void atomicComponentsMatchTheirModels() throws IOException {
        assertMatches("Controller.arc", new Controller());
        assertMatches("Planner.arc", new Planner((g, s) -> null));
        assertMatches("StateProvider.arc", new StateProvider(() -> null));
        assertMatches("ActionExecutor.arc", new ActionExecutor(NO_ACTIONS));
        assertMatches("PlanVerifier.arc", new PlanVerifier((g, s, p) -> Optional.empty()));
        assertMatches("RemoteOperator.arc", new RemoteOperator());
    }

    private static void assertMatches(String model, Component c) throws IOException {
        String text = Files.readString(MODELS.resolve(model)).replaceAll("(?s)/\\*.*?\\*/", "");
        assertEquals(modelPorts(text), javaPorts(c), model + ": ports");
        if (c instanceof ComposedComponent composed) {
            assertEquals(modelSubcomponents(text), javaSubcomponents(composed), model + ": subcomponents");
            assertEquals(modelConnectors(text), javaConnectors(composed), model + ": connectors");
        }
    }

    private static TreeSet<String> modelPorts(String text) {
        TreeSet<String> ports = new TreeSet<>();
        Matcher m = PORT.matcher(text);
        while (m.find()) {
            ports.add(m.group(1) + " " + m.group(2) + " " + m.group(3));
        }
        return ports;
    }

    private static TreeSet<String> javaPorts(Component c) {
        TreeSet<String> ports = new TreeSet<>();
        for (Port<?> p : c.ports()) {
            if (!(c instanceof ComposedComponent && p.name().equals(ComposedComponent.FAULTS))) {
                ports.add((p instanceof InPort ? "in " : "out ") + p.type().getSimpleName() + " " + p.name());
            }
        }
        return ports;
    }

    private static TreeSet<String> modelSubcomponents(String text) {
        TreeSet<String> subs = new TreeSet<>();
        Matcher m = SUB.matcher(text);
        while (m.find()) {
            subs.add(m.group(1) + " " + m.group(2));
        }
        return subs;
    }

    private static TreeSet<String> javaSubcomponents(ComposedComponent c) {
        TreeSet<String> subs = new TreeSet<>();
        c.subcomponents().forEach(s -> subs.add(s.getClass().getSimpleName() + " " + s.name()));
        return subs;
    }

    private static TreeSet<String> modelConnectors(String text) {
        TreeSet<String> connectors = new TreeSet<>();
        Matcher m = CONNECTOR.matcher(text);
        while (m.find()) {
            for (String target : m.group(2).split(",")) {
                connectors.add(m.group(1) + " -> " + target.trim());
            }
        }
        return connectors;
    }

    private static TreeSet<String> javaConnectors(ComposedComponent c) {
        List<Port<?>> sources = new ArrayList<>();
        c.ports().stream().filter(p -> p instanceof InPort).forEach(sources::add);
        c.subcomponents().forEach(s -> s.ports().stream().filter(p -> p instanceof OutPort).forEach(sources::add));
        TreeSet<String> connectors = new TreeSet<>();
        for (Port<?> from : sources) {
            for (Port<?> to : from.targets()) {
                connectors.add(local(c, from) + " -> " + local(c, to));
            }
        }
        return connectors;
    }

    private static String local(ComposedComponent c, Port<?> p) {
        return p.owner() == c ? p.name() : p.owner().name() + "." + p.name();
    }
}
