package org.triad.building;

/**
 * A robot that already acts on a {@link SharedWorld} itself (a {@link ModelRobot} behind a platform
 * provider's robot), so the building does not wrap it again to observe it.
 */
public interface BuildingMember {
    SharedWorld world();
}
