package org.triad.examples.logistics;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import generated.logisticsdomain.IWorld;
import generated.logisticsdomain.domain.Room;
import generated.logisticsdomain.domain.WayPoint;

/** A handcrafted world: a fixed floor plan of waypoints and rooms, connected in both directions. */
public class FloorPlan implements IWorld {
	private final List<WayPoint> wayPoints = new ArrayList<>();
	private final List<Room> rooms = new ArrayList<>();
	private final Set<List<WayPoint>> connections = new HashSet<>();

	public WayPoint wayPoint(String name) {
		WayPoint w = new WayPoint(name);
		wayPoints.add(w);
		return w;
	}

	public Room room(String name, String label) {
		Room r = new Room(name);
		r.setName(label);
		rooms.add(r);
		return r;
	}

	public FloorPlan connect(WayPoint a, WayPoint b) {
		connections.add(List.of(a, b));
		connections.add(List.of(b, a));
		return this;
	}

	@Override
	public boolean adj(WayPoint a, WayPoint b) {
		return connections.contains(List.of(a, b));
	}

	@Override
	public List<WayPoint> wayPoints() {
		return List.copyOf(wayPoints);
	}

	@Override
	public List<Room> rooms() {
		return List.copyOf(rooms);
	}
}
