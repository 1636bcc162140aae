package org.triad.building.traffic;

import java.util.List;

/** A floor map the traffic control cannot work with; the message lists every problem, one a line. */
public final class TrafficMapException extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;
    private final List<String> problems;

    TrafficMapException(List<String> problems) {
        super("bad traffic map: " + String.join("; ", problems));
        this.problems = List.copyOf(problems);
    }

    /** Each problem in one sentence naming the node, edge or area. */
    public List<String> problems() {
        return problems;
    }
}
