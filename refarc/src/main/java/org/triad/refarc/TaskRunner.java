package org.triad.refarc;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.function.Consumer;

import org.triad.refarc.model.DryRunWorld;
import org.triad.refarc.model.SchemaGoalPlanner;
import org.triad.runtime.app.DomainObject;
import org.triad.runtime.app.State;
import org.triad.runtime.app.TaskInstance;
import org.triad.runtime.schema.AppSchema;
import org.triad.runtime.schema.GoalSolver;
import org.triad.runtime.schema.ModelTask;
import org.triad.runtime.schema.Param;
import org.triad.runtime.schema.TaskSchema;

/**
 * An application's RefArc for running tasks from Java: built from the generated schema and the
 * StateProvider and ActionExecutor around the application's robot and world (the generated
 * {@code <App>RefArc.of(robot, world)} does that), or over a situation ({@link #dry}); runs a task by
 * name and arguments to its end and hands every {@link Status} to the observers as it happens.
 *
 * <pre>{@code
 * TaskRunner refArc = LogisticsDomainRefArc.of(robot, world).onStatus(System.out::println);
 * RefArcRun run = refArc.run("GoTo", "office", "lab");     // objects by name, as the world lists them
 * run.outcome();                                           // COMPLETED or ABORTED, run.statuses() all events
 * }</pre>
 */
public final class TaskRunner {
	private final AppSchema schema;
	private final StateSource state;
	private final ActionRunner actions;
	private final GoalPlanner planner;
	private final List<Consumer<? super Status>> observers = new ArrayList<>();

	/** RefArc over this state source and action runner, planning with Triad's engine (30 s a goal). */
	public TaskRunner(AppSchema schema, StateSource state, ActionRunner actions) {
		this(schema, state, actions, new SchemaGoalPlanner(new GoalSolver(Objects.requireNonNull(schema, "schema"))));
	}

	/** RefArc with a planner of one's own (e.g. {@code new SchemaGoalPlanner(new GoalSolver(schema, pddl4j, timeout))}). */
	public TaskRunner(AppSchema schema, StateSource state, ActionRunner actions, GoalPlanner planner) {
		this.schema = Objects.requireNonNull(schema, "schema");
		this.state = Objects.requireNonNull(state, "state");
		this.actions = Objects.requireNonNull(actions, "actions");
		this.planner = Objects.requireNonNull(planner, "planner");
	}

	/** RefArc over a dry world: a robot and world doing what their postconditions say, starting in {@code situation}. */
	public static TaskRunner dry(AppSchema schema, State situation) {
		DryRunWorld world = new DryRunWorld(schema, situation);
		return new TaskRunner(schema, world, world);
	}

	/** Hands every Status event of later runs to {@code observer} as it happens. */
	public TaskRunner onStatus(Consumer<? super Status> observer) {
		observers.add(Objects.requireNonNull(observer, "observer"));
		return this;
	}

	/**
	 * Runs the task of this name to its end. An argument for an object parameter is the object or its name
	 * among the objects the world lists now; others are values ({@code 3}, {@code "gauze"}, {@code true}).
	 *
	 * @throws IllegalArgumentException for an unknown task, a wrong number of arguments, an unknown object or one of the wrong type
	 */
	public RefArcRun run(String task, Object... args) {
		TaskSchema t = schema.task(task).orElseThrow(() -> new IllegalArgumentException(
				"application " + schema.name() + " has no task '" + task + "'; its tasks: " + schema.tasks().keySet()));
		if (t.params().size() != args.length) {
			throw new IllegalArgumentException("task " + task + t.params().stream().map(p -> p.type() + " " + p.name()).toList()
					+ " takes " + t.params().size() + " argument(s), not " + args.length);
		}
		State now = observe();
		List<Object> values = new ArrayList<>();
		for (int i = 0; i < args.length; i++) {
			values.add(argument(t, t.params().get(i), args[i], now));
		}
		return run(new ModelTask(schema, task, values));
	}

	/** Runs a task instance (a generated task class, e.g. {@code new GoTo(office, lab)}) to its end. */
	public RefArcRun run(TaskInstance task) {
		return new RefArcRunner(state, planner, actions).run(task, status -> observers.forEach(o -> o.accept(status)));
	}

	/** The world now, to find the objects the arguments name. */
	private State observe() {
		try {
			return state.currentState();
		} catch (RuntimeException e) {
			throw e;
		} catch (Exception e) {
			throw new IllegalStateException("cannot observe the world to find the task's objects: " + e.getMessage(), e);
		}
	}

	private Object argument(TaskSchema task, Param p, Object arg, State now) {
		if (!schema.types().containsKey(p.type())) {
			return arg; // a value parameter: the planner and the goals check its type
		}
		Optional<DomainObject> object = arg instanceof DomainObject o ? Optional.of(o)
				: arg instanceof String name ? now.object(name) : Optional.empty();
		if (object.isEmpty()) {
			throw new IllegalArgumentException("task " + task.name() + ": parameter " + p.name() + " takes a " + p.type()
					+ ", and the world lists no object '" + arg + "'; it lists " + now.objects().keySet());
		}
		if (!schema.isSubtype(object.get().typeName(), p.type())) {
			throw new IllegalArgumentException("task " + task.name() + ": parameter " + p.name() + " takes a " + p.type() + ", not "
					+ object.get().typeName() + " '" + object.get().name() + "'");
		}
		return now.objects().getOrDefault(object.get().name(), object.get());
	}
}
