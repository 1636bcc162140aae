package org.triad.tests.hospital;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.examples.hospital.HospitalFloor;
import org.triad.examples.hospital.HospitalSimulation;
import org.triad.generator.SchemaBuilder;
import org.triad.generator.SituationReader;
import org.triad.runtime.app.Atom;
import org.triad.runtime.app.State;

import generated.hospital.HospitalStateProvider;

/** What the generated StateProvider observes on the simulated hospital agrees with the models. */
class HospitalSimulationSituationTest {

    @Test
    void theSimulatedHospitalStartsInTheMorningSituationOfTheModels() {
        LoadedApplication app = ApplicationAssembler.load(Path.of("..", "models", "hospital", "src", "main", "models"));
        assertFalse(app.hasErrors(), () -> app.diagnostics().toString());
        State morning = SituationReader.read(app.application().getSituations().stream().filter(s -> s.getName().equals("Morning"))
                .findFirst().orElseThrow(), SchemaBuilder.build(app.application()));

        HospitalSimulation h = new HospitalSimulation(1);
        State observed = new HospitalStateProvider(h.courier(), h.building()).currentState();
        assertEquals(withoutDistances(morning), withoutDistances(observed));
        // the building measures every pair of waypoints; the situation states the corridors' lengths, to a decimetre
        int lengths = 0;
        for (Map.Entry<Atom, Object> e : morning.values().entrySet()) {
            if (isDistance(e.getKey())) {
                Object measured = observed.valueOf(e.getKey()).orElseThrow(() -> new AssertionError("no length observed for " + e.getKey()));
                assertEquals(((Number) e.getValue()).doubleValue(), ((Number) measured).doubleValue(), 0.1, e.getKey().toString());
                lengths++;
            }
        }
        assertTrue(lengths > 0, "the Morning situation states the corridors' lengths");
    }

    private static boolean isDistance(Atom a) {
        return a.actor().equals("Building") && a.property().equals("distance");
    }

    private static State withoutDistances(State s) {
        State.Builder b = State.builder().objects(s.objects().values());
        s.values().forEach((atom, value) -> {
            if (!isDistance(atom)) {
                b.value(atom, value);
            }
        });
        return b.build();
    }

    @Test
    void aDoorTheRobotHasSeenClosedDisconnectsItsCorridorSegment() {
        HospitalSimulation h = new HospitalSimulation(1);
        HospitalStateProvider provider = new HospitalStateProvider(h.courier(), h.building());
        Atom c2c3 = Atom.of("Building", "adj", h.objects().waypoint("c2"), h.objects().waypoint("c3"));
        Atom c3c2 = Atom.of("Building", "adj", h.objects().waypoint("c3"), h.objects().waypoint("c2"));
        h.sim().closeDoor(HospitalFloor.FIRE_DOOR);
        assertTrue(provider.currentState().holds(c2c3), "the robot in the lobby has not seen the door");

        h.courier().robot().moveTo("c2");
        h.courier().robot().moveTo("c3");
        assertTrue(h.courier().robot().knownClosedDoors().contains(HospitalFloor.FIRE_DOOR));
        State s = provider.currentState();
        assertFalse(s.holds(c2c3));
        assertFalse(s.holds(c3c2));
        assertTrue(s.holds(Atom.of("Building", "adj", h.objects().waypoint("c1"), h.objects().waypoint("c2"))));
    }
}
