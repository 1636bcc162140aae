package org.triad.building.traffic;

import java.util.List;

/** What the reservation table answers a robot asking for the next stretch of its route. */
public sealed interface Decision permits Decision.Granted, Decision.Waiting, Decision.Refused {
    String robot();

    /**
     * The robot holds the stretch: it may drive {@code stretch} (from its old decision point to its new one),
     * and the route goes on with {@code horizon} (empty at the route's end), not yet released.
     */
    record Granted(String robot, List<String> stretch, List<String> horizon) implements Decision {
        public Granted {
            stretch = List.copyOf(stretch);
            horizon = List.copyOf(horizon);
        }

        /** The robot's new decision point: where it stops unless the base is extended. */
        public String decisionPoint() {
            return stretch.get(stretch.size() - 1);
        }
    }

    /** The robot queues for the stretch; it stops at its decision point until the table grants it. */
    record Waiting(String robot, Wait queued) implements Decision {
    }

    /**
     * The robot may not wait for this stretch: waiting would close a wait-for cycle (a deadlock), or the
     * stretch is blocked (a lost robot, an obstacle). The action fails with {@code reason}, and RefArc re-plans.
     * {@code cycle} names the robots the wait would have closed a cycle with (the robot first), empty for a block:
     * when the robot cannot get out of the way, one of the others can (a dispatcher's choice).
     */
    record Refused(String robot, String reason, List<String> cycle) implements Decision {
        public Refused {
            cycle = List.copyOf(cycle);
        }

        /** Refused for a blocked place: no cycle. */
        public Refused(String robot, String reason) {
            this(robot, reason, List.of());
        }
    }
}
