package ${package};

import java.util.Objects;

import generated.${appName.toLowerCase()}.IRobot;
import generated.${appName.toLowerCase()}.domain.Medicine;
import generated.${appName.toLowerCase()}.domain.Place;

/**
 * A robot in memory that does what its actions' postconditions say, in a {@link FakeStore}. Replace it with
 * one that drives your platform (ROS, VDA 5050, a simulator): each action returns when it has ended, true
 * when it succeeded.
 */
public class FakeRunner implements IRobot {
	private final FakeStore store;
	private Place at;
	private Medicine held;

	public FakeRunner(FakeStore store, Place start) {
		this.store = Objects.requireNonNull(store, "store");
		this.at = Objects.requireNonNull(start, "start");
	}

	@Override
	public boolean move(Place src, Place dst) {
		if (!at.equals(src) || !store.linked(src, dst)) {
			return false;
		}
		at = dst;
		return true;
	}

	@Override
	public boolean pick(Medicine m, Place p) {
		if (held != null || !at.equals(p) || !store.stockedAt(m, p)) {
			return false;
		}
		store.take(m, p);
		held = m;
		return true;
	}

	@Override
	public boolean drop(Medicine m, Place p) {
		if (!m.equals(held) || !at.equals(p)) {
			return false;
		}
		store.put(m, p);
		held = null;
		return true;
	}

	@Override
	public Place at() {
		return at;
	}

	@Override
	public boolean holds(Medicine m) {
		return m.equals(held);
	}

	@Override
	public boolean handEmpty() {
		return held == null;
	}
}
