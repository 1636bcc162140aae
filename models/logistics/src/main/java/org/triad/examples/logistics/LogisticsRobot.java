package org.triad.examples.logistics;

import java.util.Objects;

import generated.logisticsdomain.IRobot;
import generated.logisticsdomain.domain.WayPoint;

/**
 * The handcrafted implementation of the generated {@code IRobot} (the paper's Fig. 4): here a robot
 * that drives along the floor plan's connections; a real one would call its platform's middleware.
 */
public class LogisticsRobot implements IRobot {
	private final FloorPlan floor;
	private WayPoint location;

	public LogisticsRobot(FloorPlan floor, WayPoint start) {
		this.floor = Objects.requireNonNull(floor, "floor");
		this.location = Objects.requireNonNull(start, "start");
	}

	@Override
	public boolean move(WayPoint src, WayPoint dst) {
		if (!location.equals(src) || !floor.adj(src, dst)) {
			return false;
		}
		location = dst;
		return true;
	}

	@Override
	public WayPoint loc() {
		return location;
	}
}
