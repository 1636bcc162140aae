package org.triad.examples.hospital.fleet;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.triad.examples.hospital.HospitalObjects;
import org.triad.runtime.app.GroundAction;

/**
 * Under traffic control the fleet's planner prices an action that takes a person along one step higher, so a plan leads
 * a person only where its goal needs it (the service's mixed benchmark: plans for {@code GoTo} guided Alice out of the
 * lobby while another task held her).
 */
class LeadingAPersonCostTest {
    @Test
    void guidingOrWalkingWithAPersonCostsAStepMoreThanDriving() {
        HospitalObjects o = new HospitalObjects();
        GroundAction guide = new GroundAction("Courier", "guide", List.of(o.person("alice"), o.waypoint("lobby"), o.waypoint("c4")));
        GroundAction walk = new GroundAction("Building", "walk", List.of(o.person("bob"), o.waypoint("c5"), o.waypoint("ward3")));
        GroundAction move = new GroundAction("Courier", "move", List.of(o.waypoint("lobby"), o.waypoint("c4")));
        GroundAction pick = new GroundAction("Courier", "pick", List.of(o.item("gauze"), o.waypoint("storage")));
        assertEquals(1, VdaHospitalFleet.LEADING_A_PERSON.extra(guide));
        assertEquals(1, VdaHospitalFleet.LEADING_A_PERSON.extra(walk));
        assertEquals(0, VdaHospitalFleet.LEADING_A_PERSON.extra(move));
        assertEquals(0, VdaHospitalFleet.LEADING_A_PERSON.extra(pick));
    }

    @Test
    void aGuideAlongACongestedEdgeCostsWhatTheMoveCostsAndAStepMore() {
        HospitalObjects o = new HospitalObjects();
        // c6 -> c5 congested: 3 steps of expected wait for whoever drives it
        org.triad.runtime.schema.ActionCosts congestion = a -> a.action().equals("move") && a.args().equals(List.of(o.waypoint("c6"), o.waypoint("c5"))) ? 3 : 0;
        org.triad.runtime.schema.ActionCosts costs = VdaHospitalFleet.leadingAPerson(congestion);
        GroundAction guide = new GroundAction("Courier", "guide", List.of(o.person("alice"), o.waypoint("c6"), o.waypoint("c5")));
        GroundAction move = new GroundAction("Courier", "move", List.of(o.waypoint("c6"), o.waypoint("c5")));
        assertEquals(4, costs.extra(guide), "a guide is never the cheap way round a congested edge");
        assertEquals(3, congestion.extra(move) + costs.extra(move));
        assertEquals(1, costs.extra(new GroundAction("Courier", "guide", List.of(o.person("alice"), o.waypoint("c4"), o.waypoint("c5")))));
    }
}
