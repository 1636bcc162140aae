package org.triad.runtime.schema;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.triad.runtime.app.Atom;
import org.triad.runtime.app.GoalInstance;
import org.triad.runtime.app.Plan;
import org.triad.runtime.app.State;
import org.triad.planner.PddlStep;
import org.triad.planner.SolveResult;
import org.triad.planner.UnreachableGoal;
import org.triad.planner.PddlPlanner;
import org.triad.planner.TriadEngine;

/**
 * Solves a goal of an application from a state: the bridge from goals to PDDL to plans. Translates
 * the goal to the planner's typed PDDL model ({@link PddlTranslator}), runs the configured
 * {@link PddlPlanner}, reads the plan back into the application's actions. Failures are results with
 * a reason, never exceptions. (RefArc's Planner component plans through it, see
 * {@code refarc.model.SchemaGoalPlanner}.)
 */
public final class GoalSolver {
	private final AppSchema schema;
	private final PddlTranslator translator;
	private final PddlPlanner planner;
	private final Duration timeout;
	/** Extra costs of actions (congestion), or null for the shortest plan. */
	private final ActionCosts costs;

	public GoalSolver(AppSchema schema) {
		this(schema, new TriadEngine(), Duration.ofSeconds(30));
	}

	public GoalSolver(AppSchema schema, PddlPlanner planner, Duration timeout) {
		this(schema, planner, timeout, null);
	}

	private GoalSolver(AppSchema schema, PddlPlanner planner, Duration timeout, ActionCosts costs) {
		this.schema = schema;
		this.translator = new PddlTranslator(schema);
		this.planner = planner;
		this.timeout = timeout;
		this.costs = costs;
	}

	/**
	 * This solver asking for the plan of least cost, every action costing {@code 1 + costs.extra(action)}
	 * (the congestion hook: a move's expected wait), instead of the shortest plan.
	 */
	public GoalSolver withCosts(ActionCosts costs) {
		return new GoalSolver(schema, planner, timeout, java.util.Objects.requireNonNull(costs, "costs"));
	}

	/**
	 * A plan, or the reason there is none. {@code proven} marks a failure the planner proved: no plan reaches the
	 * goal from this state (the search space exhausted, or a goal shown unreachable), so planning again from the
	 * same state gives the same answer. A timeout, a spent work budget, a model or translation error and a fault
	 * of the planner are not proven.
	 */
	public record Outcome(Plan plan, String failure, boolean proven) {
		public Outcome(Plan plan, String failure) {
			this(plan, failure, false);
		}

		public Outcome {
			if (proven && plan != null) {
				throw new IllegalArgumentException("a plan proves nothing unsolvable");
			}
		}

		/** A failure the planner proved (see the class comment): no plan from this state. */
		static Outcome unsolvable(String failure) {
			return new Outcome(null, failure, true);
		}

		public boolean planned() {
			return plan != null;
		}
	}

	public Outcome plan(String goal, List<Object> args, State from) {
		try {
			ModelGoal g = new ModelGoal(schema, goal, args);
			return plan(g.schema(), g.binding(), from);
		} catch (ModelEvaluationException | PddlTranslationException e) {
			return new Outcome(null, e.getMessage());
		}
	}

	public Outcome plan(GoalSchema goal, Map<String, Object> binding, State from) {
		try {
			PddlTranslator.Task task = translator.translate(from, goal, binding);
			SolveResult result;
			if (costs == null) {
				result = planner.solve(task.domain(), task.problem(), timeout);
			} else {
				ActionCosts.Costed costed = ActionCosts.apply(task, costs);
				result = planner.solve(costed.domain(), costed.problem(), timeout);
			}
			List<UnreachableGoal> unreachable = result.unreachable();
			if (unreachable.isEmpty() && result.status() == SolveResult.Status.UNSOLVABLE && !task.domain().functions().isEmpty()) {
				// the numeric search says only that nothing reaches the goal: the facts, numbers left out, say what is missing
				unreachable = planner.solve(FactsOnly.domain(task.domain()), FactsOnly.problem(task.problem()), timeout).unreachable();
			}
			if (!unreachable.isEmpty()) {
				return Outcome.unsolvable("no plan: " + new UnreachableGoalText(schema, task.names())
						.describe(UnreachableGoalText.goalLabel(goal, binding), unreachable));
			}
			if (!result.isSolved()) {
				return new Outcome(null, switch (result.status()) {
					case UNSOLVABLE -> "no plan: " + (result.message().isEmpty() ? "the goal is unreachable" : result.message());
					case TIMEOUT -> "no plan within " + timeout.toMillis() + " ms";
					default -> "planner error: " + result.message();
				}, result.status() == SolveResult.Status.UNSOLVABLE);
			}
			List<PddlStep> steps = result.plan().steps();
			return new Outcome(task.plan(steps.stream().map(PddlStep::name).toList(), steps.stream().map(PddlStep::args).toList()), null);
		} catch (PddlTranslationException | ModelEvaluationException e) {
			return new Outcome(null, e.getMessage());
		} catch (RuntimeException e) {
			return new Outcome(null, "planning failed: " + e);
		}
	}

	/**
	 * Plans {@code goal} so that the goals {@code then} (the rest of its task) stay reachable from where its
	 * plan ends: a task does not strand its robot. The goal's own plan is kept when the rest can be planned,
	 * goal by goal, from the state it ends in (what the paper's Controller will do); otherwise the goal and
	 * the rest are planned as one lookahead and only the part that reaches {@code goal} is returned, to be
	 * executed before the next goal is planned again from the observed state. A task that cannot be
	 * completed at all fails here, before the robot moves, naming the goal that cannot be reached and the
	 * quantities where it fails. Applications whose actions change no quantity (none, or only distances
	 * charged as costs) are planned goal by goal as before: nothing there is used up by reaching a goal.
	 */
	public Outcome plan(GoalInstance goal, List<? extends GoalInstance> then, State from) {
		Outcome first = plan(goal.name(), goal.args(), from);
		if (!translator.changesQuantities()) {
			return first;
		}
		if (!first.planned()) {
			String needs = needs(goal, from);
			// no quantity in the way: the failure names the facts that are missing, and says it all
			return new Outcome(null, needs.isEmpty() ? first.failure() : goal.describe() + " unreachable: " + needs + "(" + first.failure() + ")",
					first.proven());
		}
		if (then.isEmpty()) {
			return first;
		}
		try {
			String stranded = strandedBy(first.plan(), goal, then, from);
			if (stranded == null) {
				return first;
			}
			List<PddlTranslator.Stage> stages = new ArrayList<>();
			List<GoalInstance> all = new ArrayList<>();
			all.add(goal);
			all.addAll(then);
			for (GoalInstance g : all) {
				ModelGoal m = new ModelGoal(schema, g.name(), g.args());
				stages.add(new PddlTranslator.Stage(m.schema().condition(), m.binding()));
			}
			PddlTranslator.Task task = translator.translateSequence(from, stages, goal.name() + "-and-" + then.size() + "-more");
			SolveResult result = planner.solve(task.domain(), task.problem(), timeout);
			if (result.isSolved()) {
				List<PddlStep> steps = result.plan().steps();
				return new Outcome(task.planUntilReached(steps.stream().map(PddlStep::name).toList(), steps.stream().map(PddlStep::args).toList()), null);
			}
			// the whole task proven impossible from here, not just the goal-by-goal plans
			return new Outcome(null, stranded, result.status() == SolveResult.Status.UNSOLVABLE);
		} catch (PddlTranslationException | ModelEvaluationException e) {
			return new Outcome(null, e.getMessage());
		} catch (RuntimeException e) {
			return new Outcome(null, "planning failed: " + e);
		}
	}

	/** Why the rest of the task cannot be reached, goal by goal, after {@code plan}; null when it can. */
	private String strandedBy(Plan plan, GoalInstance goal, List<? extends GoalInstance> then, State from) {
		Transitions transitions = new Transitions(schema);
		State state = from;
		for (var a : plan.actions()) {
			state = transitions.apply(a, state);
		}
		GoalInstance previous = goal;
		for (GoalInstance next : then) {
			ModelGoal m = new ModelGoal(schema, next.name(), next.args());
			if (!m.isSatisfiedIn(state)) {
				Outcome o = plan(next.name(), next.args(), state);
				if (!o.planned()) {
					String needs = needs(next, state);
					return next.describe() + " unreachable" + (needs.isEmpty() ? " " : ": " + needs) + "after " + previous.describe() + " (" + o.failure() + ")";
				}
				for (var a : o.plan().actions()) {
					state = transitions.apply(a, state);
				}
			}
			previous = next;
		}
		return null;
	}

	/** A quantity's value standing in for "as much as the trip wants" when its need is measured. */
	static final double PLENTY = 1e6;

	/**
	 * The quantities without arguments (a battery, a load limit) in a state that stand in the way of {@code goal},
	 * as the models name them, each with what reaching the goal needs of it: {@code Courier.battery() is 12.0 and
	 * the trip needs 30.0 }. The need is measured on a plan for the goal from the same state with only that
	 * quantity made plentiful ({@link #PLENTY}): the least start from which that plan runs, which is how far it draws
	 * the quantity down plus what its preconditions keep in hand (a battery reserve); quantities are separated by
	 * commas. Plans are of least cost, so with moves
	 * costing their length it is what the shortest trip draws, an upper bound on the least need. A quantity the
	 * plan does not draw down (a payload limit) gets "and the trip needs more". A quantity whose plenty does not
	 * help (the load, a drain per metre, a battery where an item is missing) is left out; when none helps, this is
	 * "" and the planner's reason (the facts missing) is the whole story.
	 */
	private String needs(GoalInstance goal, State state) {
		List<String> parts = new ArrayList<>();
		for (var e : state.values().entrySet()) {
			var atom = e.getKey();
			if (!atom.args().isEmpty() || !translator.isQuantity(atom.actor(), atom.property()) || !(e.getValue() instanceof Number value)) {
				continue;
			}
			StringBuilder b = new StringBuilder();
			b.append(atom.actor()).append('.').append(atom.property()).append("() is ").append(number(value.doubleValue(), value instanceof Integer));
			State plenty = state.toBuilder().value(atom, value instanceof Integer ? (Object) (int) PLENTY : (Object) PLENTY).build();
			Outcome o = plan(goal.name(), goal.args(), plenty);
			if (o.planned()) {
				double least = PLENTY;
				State s = plenty;
				Transitions transitions = new Transitions(schema);
				for (var a : o.plan().actions()) {
					s = transitions.apply(a, s);
					least = Math.min(least, s.valueOf(atom).map(v -> ((Number) v).doubleValue()).orElse(PLENTY));
				}
				double drawn = PLENTY - least;
				if (drawn > 1e-9) {
					double need = leastStart(o.plan(), atom, state, drawn, value instanceof Integer);
					b.append(" and the trip needs ").append(number(need, value instanceof Integer));
				} else {
					b.append(" and the trip needs more");
				}
				parts.add(b.toString());
			}
		}
		return parts.isEmpty() ? "" : String.join(", ", parts) + " ";
	}

	/**
	 * The least value of {@code atom} from which {@code plan} can be executed in {@code state}: at least what it draws,
	 * more where its preconditions keep something in hand (a move that must leave a battery reserve needs the draw
	 * plus the reserve). Found by bisection between the draw and {@link #PLENTY}, where the plan was found, as
	 * executing a plan that draws a quantity down only gets easier the more of it there is at the start.
	 */
	private double leastStart(Plan plan, Atom atom, State state, double drawn, boolean integer) {
		double low = integer ? Math.ceil(drawn) : drawn;
		if (executable(plan, atom, state, low, integer)) {
			return low;
		}
		double high = PLENTY;
		// low fails and high succeeds: halve the gap down to a thousandth (a whole unit for an int)
		while (high - low > (integer ? 1 : 1e-4)) {
			double mid = integer ? Math.floor((low + high) / 2) : (low + high) / 2;
			if (executable(plan, atom, state, mid, integer)) {
				high = mid;
			} else {
				low = mid;
			}
		}
		return high;
	}

	private boolean executable(Plan plan, Atom atom, State state, double start, boolean integer) {
		Transitions transitions = new Transitions(schema);
		State s = state.toBuilder().value(atom, integer ? (Object) (int) start : (Object) start).build();
		for (var a : plan.actions()) {
			if (!transitions.isApplicable(a, s)) {
				return false;
			}
			s = transitions.apply(a, s);
		}
		return true;
	}

	/** A need as the models write numbers: an int as an int, a double rounded to 3 decimals ({@code 30.0}, {@code 2.47}). */
	private static String number(double v, boolean integer) {
		if (integer) {
			return Long.toString(Math.round(v));
		}
		return Double.toString(Math.round(v * 1000) / 1000.0);
	}

	public PddlTranslator translator() {
		return translator;
	}
}
