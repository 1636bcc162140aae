package ${package};

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.triad.generator.Situations;
import org.triad.refarc.RefArcRun;
import org.triad.refarc.Status;
import org.triad.refarc.TaskRunner;
import org.triad.runtime.app.Atom;
import org.triad.runtime.app.State;

import generated.${appName.toLowerCase()}.${appName}RefArc;
import generated.${appName.toLowerCase()}.${appName}Schema;
import generated.${appName.toLowerCase()}.domain.Medicine;
import generated.${appName.toLowerCase()}.domain.Place;
import generated.${appName.toLowerCase()}.domain.Cabinet;

/** The task Restock through RefArc: planned at runtime, on the fake robot and world, and in a dry world. */
class RestockTest {

	@Test
	void restockRunsThroughRefArcOnTheFakeRobotAndWorld() {
		FakeStore store = new FakeStore();
		Place dock = store.place("dock");
		Cabinet a1 = store.cabinet("a1", "A1");
		Cabinet b2 = store.cabinet("b2", "B2");
		Medicine aspirin = store.medicine("aspirin", "Aspirin 500 mg");
		store.link(dock, a1).link(dock, b2);
		store.put(aspirin, a1);
		List<Status> seen = new ArrayList<>();

		RefArcRun run = ${appName}RefArc.of(new FakeRunner(store, dock), store)
				.onStatus(seen::add)
				.run("Restock", "aspirin", "a1", "b2");

		assertEquals(RefArcRun.Outcome.COMPLETED, run.outcome(), String.join("\n", run.log()));
		assertTrue(store.stockedAt(aspirin, b2));
		assertFalse(store.stockedAt(aspirin, a1));
		assertEquals(run.statuses(), seen);
	}

	@Test
	void restockInTheMorningSituationInADryWorld() {
		Situations situations = Situations.load(Path.of("src/main/models"), ${appName}Schema.class);
		State morning = situations.state("Morning");
		RefArcRun run = TaskRunner.dry(${appName}Schema.SCHEMA, morning).run("Restock", "aspirin", "a1", "b2");
		assertEquals(RefArcRun.Outcome.COMPLETED, run.outcome(), String.join("\n", run.log()));

		State noon = situations.state("Noon");
		Medicine aspirin = (Medicine) noon.object("aspirin").orElseThrow();
		assertTrue(noon.holds(Atom.of("Store", "stockedAt", aspirin, noon.object("b2").orElseThrow())));
		assertFalse(noon.holds(Atom.of("Store", "stockedAt", aspirin, noon.object("a1").orElseThrow())));
	}
}
