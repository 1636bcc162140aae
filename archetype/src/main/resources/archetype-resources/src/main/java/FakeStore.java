package ${package};

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import generated.${appName.toLowerCase()}.IWorld;
import generated.${appName.toLowerCase()}.domain.Medicine;
import generated.${appName.toLowerCase()}.domain.Place;
import generated.${appName.toLowerCase()}.domain.Cabinet;

/**
 * A world in memory: the places, which are linked, and where each medicine is. Replace it with one that
 * asks your building (a map server, a stock database) when the application meets the real world.
 */
public class FakeStore implements IWorld {
	private final List<Place> places = new ArrayList<>();
	private final List<Cabinet> cabinets = new ArrayList<>();
	private final List<Medicine> medicines = new ArrayList<>();
	private final Set<List<Object>> links = new HashSet<>();
	private final Set<List<Object>> stock = new HashSet<>();

	public Place place(String name) {
		Place p = new Place(name);
		places.add(p);
		return p;
	}

	public Cabinet cabinet(String name, String label) {
		Cabinet c = new Cabinet(name);
		c.setLabel(label);
		cabinets.add(c);
		return c;
	}

	public Medicine medicine(String name, String label) {
		Medicine m = new Medicine(name);
		m.setLabel(label);
		medicines.add(m);
		return m;
	}

	/** Links two places both ways. */
	public FakeStore link(Place a, Place b) {
		links.add(List.of(a, b));
		links.add(List.of(b, a));
		return this;
	}

	public void put(Medicine m, Place p) {
		stock.add(List.of(m, p));
	}

	public void take(Medicine m, Place p) {
		stock.remove(List.of(m, p));
	}

	@Override
	public boolean linked(Place a, Place b) {
		return links.contains(List.of(a, b));
	}

	@Override
	public boolean stockedAt(Medicine m, Place p) {
		return stock.contains(List.of(m, p));
	}

	@Override
	public List<Place> places() {
		return List.copyOf(places); // cabinets are listed by cabinets(); each object counts once
	}

	@Override
	public List<Cabinet> cabinets() {
		return List.copyOf(cabinets);
	}

	@Override
	public List<Medicine> medicines() {
		return List.copyOf(medicines);
	}
}
