package org.triad.examples.hospital.vda5050;

import java.util.HashMap;
import java.util.Map;
import java.util.Optional;

import org.triad.examples.hospital.HospitalFloor;

/**
 * What master control knows about the hospital that no AGV reports: where the items lie and where the
 * people stand, from the Morning situation on, updated by the actions the AGV finished (a pick takes an
 * item away, a drop puts it where the AGV stands, guiding and walking move the person along).
 */
final class HospitalKnowledge {
    private final Map<String, String> items = new HashMap<>();
    private final Map<String, String> people = new HashMap<>();

    HospitalKnowledge() {
        items.putAll(HospitalFloor.ITEM_ROOMS);
        people.put("alice", "lobby");
        people.put("bob", "ward2");
    }

    synchronized Optional<String> itemAt(String item) {
        return Optional.ofNullable(items.get(item));
    }

    synchronized void itemTaken(String item) {
        items.remove(item);
    }

    synchronized void itemPut(String item, String waypoint) {
        items.put(item, waypoint);
    }

    synchronized String personAt(String person) {
        return people.get(person);
    }

    synchronized void personMoved(String person, String waypoint) {
        people.put(person, waypoint);
    }
}
