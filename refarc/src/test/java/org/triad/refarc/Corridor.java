package org.triad.refarc;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Consumer;
import org.triad.runtime.app.Atom;
import org.triad.runtime.app.GoalInstance;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.Plan;
import org.triad.runtime.app.State;
import org.triad.runtime.app.TaskInstance;

/**
 * A scripted test application: a robot in a corridor of waypoints a-b-c-d-e that moves between
 * adjacent waypoints. The world, the planner and the action back-end can be told to misbehave at
 * exact steps, so tests can assert exact status sequences.
 */
final class Corridor {
    static final List<String> WAYPOINTS = List.of("a", "b", "c", "d", "e");
    static final Atom LOC = Atom.of("robot", "loc");

    private Corridor() {
    }

    static GroundAction move(String from, String to) {
        return new GroundAction("robot", "move", List.of(from, to));
    }

    static boolean adjacent(String x, String y) {
        return Math.abs(WAYPOINTS.indexOf(x) - WAYPOINTS.indexOf(y)) == 1 && WAYPOINTS.contains(x) && WAYPOINTS.contains(y);
    }

    static String locIn(State s) {
        return (String) s.valueOf(LOC).orElseThrow();
    }

    record IsAt(String waypoint) implements GoalInstance {
        @Override
        public String name() {
            return "IsAt";
        }

        @Override
        public List<Object> args() {
            return List.of(waypoint);
        }

        @Override
        public boolean isSatisfiedIn(State state) {
            return state.valueOf(LOC).map(waypoint::equals).orElse(false);
        }

        @Override
        public String toString() {
            return describe();
        }
    }

    record Task(String name, List<Object> args, List<GoalInstance> goals) implements TaskInstance {
        /** A task visiting the given waypoints in order, named e.g. {@code GoTo(b, d)}. */
        static Task goTo(String... waypoints) {
            List<GoalInstance> goals = new ArrayList<>();
            for (String w : waypoints) {
                goals.add(new IsAt(w));
            }
            return new Task("GoTo", List.of((Object[]) waypoints), goals);
        }

        @Override
        public String toString() {
            return describe();
        }
    }

    /** What one call of {@link World#execute} does. */
    interface Execution {
        boolean run(World w, GroundAction a) throws Exception;

        Execution OK = (w, a) -> {
            w.loc = (String) a.args().get(1);
            return true;
        };
        Execution FAIL = (w, a) -> false;
        Execution CRASH = (w, a) -> {
            throw new java.io.IOException("motor stalled");
        };

        static Execution slipTo(String where) {
            return (w, a) -> {
                w.loc = where;
                return false;
            };
        }
    }

    /** The robot's world: StateSource and ActionRunner. Records every call in {@link #log}. */
    static final class World implements StateSource, ActionRunner {
        volatile String loc;
        final List<String> log = Collections.synchronizedList(new ArrayList<>());
        private final Map<Integer, Consumer<World>> beforeFetch = new HashMap<>();
        private final Deque<Execution> executions = new ArrayDeque<>();
        private int fetches;
        private int checks;
        private Integer crashingCheck;

        World(String loc) {
            this.loc = loc;
        }

        /** Runs {@code change} right before the {@code n}-th state fetch (1-based), e.g. someone pushes the robot. */
        World beforeFetch(int n, Consumer<World> change) {
            beforeFetch.put(n, change);
            return this;
        }

        /** The {@code n}-th state fetch throws. */
        World failFetch(int n) {
            return beforeFetch(n, w -> {
                throw new IllegalStateException("sensor offline");
            });
        }

        /** The {@code n}-th precondition check throws. */
        World crashCheck(int n) {
            crashingCheck = n;
            return this;
        }

        /** What the next calls of execute do, in order; afterwards they succeed. */
        World executions(Execution... es) {
            executions.addAll(List.of(es));
            return this;
        }

        @Override
        public synchronized State currentState() {
            fetches++;
            Consumer<World> change = beforeFetch.get(fetches);
            if (change != null) {
                change.accept(this);
            }
            log.add("fetch " + loc);
            return State.builder().value(LOC, loc).build();
        }

        @Override
        public synchronized Optional<String> violatedPrecondition(GroundAction a, State now) {
            checks++;
            log.add("check " + a);
            if (crashingCheck != null && crashingCheck == checks) {
                throw new IllegalArgumentException("unknown action");
            }
            String from = (String) a.args().get(0);
            String to = (String) a.args().get(1);
            String at = locIn(now);
            if (!at.equals(from)) {
                return Optional.of("robot.loc() == " + from + " does not hold (robot is at " + at + ")");
            }
            if (!adjacent(from, to)) {
                return Optional.of(from + " and " + to + " are not adjacent");
            }
            return Optional.empty();
        }

        @Override
        public synchronized boolean execute(GroundAction a) throws Exception {
            log.add("execute " + a);
            Execution e = executions.isEmpty() ? Execution.OK : executions.poll();
            return e.run(this, a);
        }

        List<String> executed() {
            synchronized (log) {
                return log.stream().filter(l -> l.startsWith("execute ")).map(l -> l.substring(8)).toList();
            }
        }
    }

    /** What one call of {@link ScriptedPlanner#plan} does. */
    interface Planning {
        PlanningOutcome run(IsAt goal, State from) throws Exception;

        Planning SHORTEST = (g, from) -> PlanningOutcome.planned(shortest(locIn(from), g.waypoint()));

        static Planning fail(String reason) {
            return (g, from) -> PlanningOutcome.failed(reason);
        }

        /** A refusal the planner proved: no plan from this state. */
        static Planning refuse(String reason) {
            return (g, from) -> PlanningOutcome.unsolvable(reason);
        }

        static Planning crash(String message) {
            return (g, from) -> {
                throw new IllegalStateException(message);
            };
        }

        /** A corrupted plan: jumps straight to the goal. */
        Planning JUMP = (g, from) -> PlanningOutcome.planned(new Plan(List.of(move(locIn(from), g.waypoint()))));
    }

    static Plan shortest(String from, String to) {
        List<GroundAction> steps = new ArrayList<>();
        int i = WAYPOINTS.indexOf(from);
        int j = WAYPOINTS.indexOf(to);
        int dir = Integer.signum(j - i);
        for (int k = i; k != j; k += dir) {
            steps.add(move(WAYPOINTS.get(k), WAYPOINTS.get(k + dir)));
        }
        return new Plan(steps);
    }

    /** A scripted GoalPlanner: follows its script, then plans shortest paths. Records where it planned from. */
    static final class ScriptedPlanner implements GoalPlanner {
        final List<String> fromLocations = Collections.synchronizedList(new ArrayList<>());
        private final Deque<Planning> script = new ArrayDeque<>();
        private final Planning otherwise;

        private ScriptedPlanner(Planning otherwise, List<Planning> script) {
            this.otherwise = otherwise;
            this.script.addAll(script);
        }

        ScriptedPlanner(Planning... script) {
            this(Planning.SHORTEST, List.of(script));
        }

        /** Follows {@code script}, then does {@code otherwise} for ever. */
        static ScriptedPlanner thenAlways(Planning otherwise, Planning... script) {
            return new ScriptedPlanner(otherwise, List.of(script));
        }

        @Override
        public synchronized PlanningOutcome plan(GoalInstance goal, State from) throws Exception {
            fromLocations.add(goal.describe() + " from " + locIn(from));
            Planning p = script.isEmpty() ? otherwise : script.poll();
            return p.run((IsAt) goal, from);
        }

        /** The rest of the task each planning was asked to keep reachable, in order. */
        final List<String> lookaheads = Collections.synchronizedList(new ArrayList<>());

        @Override
        public PlanningOutcome plan(GoalInstance goal, List<GoalInstance> then, State from) throws Exception {
            lookaheads.add(goal.describe() + " then " + then.stream().map(GoalInstance::describe).toList());
            return plan(goal, from);
        }

        int calls() {
            return fromLocations.size();
        }
    }

    /** Checks a plan by simulating it from the state it was planned from. */
    static final PlanCheck SIMULATION = (goal, from, plan) -> {
        String at = locIn(from);
        for (GroundAction a : plan.actions()) {
            String to = (String) a.args().get(1);
            if (!adjacent(at, to)) {
                return Optional.of(a + ": " + at + " and " + to + " are not adjacent");
            }
            at = to;
        }
        return goal.isSatisfiedIn(State.builder().value(LOC, at).build()) ? Optional.empty()
                : Optional.of("the plan ends at " + at + ", not where " + goal.describe() + " holds");
    };
}
