package org.triad.runtime.schema;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

import org.triad.runtime.app.EnumValue;
import org.triad.runtime.app.GroundAction;

/**
 * Typed dispatch from a plan's actions to the platform's methods, built once per executor: one entry
 * per action of the application schema, each a method reference with typed parameters (e.g.
 * {@code .action("Courier", "move", WayPoint.class, WayPoint.class, robot::move)}), so a model and
 * hand-written platform code that disagree do not compile. The table converts a plan's arguments to
 * the parameter types (numbers to {@code double}, enum values to the generated Java enums) and
 * refuses a wrong argument with a message naming the action.
 */
public final class ActionTable {
	/** An action without parameters. */
	@FunctionalInterface
	public interface Call0 {
		boolean run();
	}

	@FunctionalInterface
	public interface Call1<A> {
		boolean run(A a);
	}

	@FunctionalInterface
	public interface Call2<A, B> {
		boolean run(A a, B b);
	}

	@FunctionalInterface
	public interface Call3<A, B, C> {
		boolean run(A a, B b, C c);
	}

	@FunctionalInterface
	public interface Call4<A, B, C, D> {
		boolean run(A a, B b, C c, D d);
	}

	@FunctionalInterface
	public interface Call5<A, B, C, D, E> {
		boolean run(A a, B b, C c, D d, E e);
	}

	@FunctionalInterface
	public interface Call6<A, B, C, D, E, F> {
		boolean run(A a, B b, C c, D d, E e, F f);
	}

	/** An action with more than six parameters: reads its typed arguments from {@link Arguments}. */
	@FunctionalInterface
	public interface CallN {
		boolean run(Arguments args);
	}

	/** A plan step's arguments, converted to the types asked for. */
	public static final class Arguments {
		private final GroundAction action;

		Arguments(GroundAction action) {
			this.action = action;
		}

		public <T> T get(int i, Class<T> type) {
			return convert(action, i, type);
		}
	}

	private interface Entry {
		boolean run(GroundAction action);
	}

	private record Key(String actor, String action) {
	}

	private final Map<Key, Entry> entries;

	private ActionTable(Map<Key, Entry> entries) {
		this.entries = Map.copyOf(entries);
	}

	/** A table for the actions of {@code schema}; {@link Builder#build} checks that every one has its entry. */
	public static Builder builder(AppSchema schema) {
		return new Builder(schema);
	}

	/** Runs {@code action} through its entry; returns what the platform's method returned. */
	public boolean execute(GroundAction action) {
		Entry e = entries.get(new Key(action.actor(), action.action()));
		if (e == null) {
			throw new IllegalArgumentException("no method for action " + action);
		}
		return e.run(action);
	}

	public static final class Builder {
		private final AppSchema schema;
		private final Map<Key, Entry> entries = new HashMap<>();

		private Builder(AppSchema schema) {
			this.schema = Objects.requireNonNull(schema, "schema");
		}

		public Builder action(String actor, String name, Call0 call) {
			return add(actor, name, 0, a -> call.run());
		}

		public <A> Builder action(String actor, String name, Class<A> ta, Call1<A> call) {
			return add(actor, name, 1, a -> call.run(convert(a, 0, ta)));
		}

		public <A, B> Builder action(String actor, String name, Class<A> ta, Class<B> tb, Call2<A, B> call) {
			return add(actor, name, 2, a -> call.run(convert(a, 0, ta), convert(a, 1, tb)));
		}

		public <A, B, C> Builder action(String actor, String name, Class<A> ta, Class<B> tb, Class<C> tc, Call3<A, B, C> call) {
			return add(actor, name, 3, a -> call.run(convert(a, 0, ta), convert(a, 1, tb), convert(a, 2, tc)));
		}

		public <A, B, C, D> Builder action(String actor, String name, Class<A> ta, Class<B> tb, Class<C> tc, Class<D> td,
				Call4<A, B, C, D> call) {
			return add(actor, name, 4, a -> call.run(convert(a, 0, ta), convert(a, 1, tb), convert(a, 2, tc), convert(a, 3, td)));
		}

		public <A, B, C, D, E> Builder action(String actor, String name, Class<A> ta, Class<B> tb, Class<C> tc, Class<D> td, Class<E> te,
				Call5<A, B, C, D, E> call) {
			return add(actor, name, 5,
					a -> call.run(convert(a, 0, ta), convert(a, 1, tb), convert(a, 2, tc), convert(a, 3, td), convert(a, 4, te)));
		}

		public <A, B, C, D, E, F> Builder action(String actor, String name, Class<A> ta, Class<B> tb, Class<C> tc, Class<D> td,
				Class<E> te, Class<F> tf, Call6<A, B, C, D, E, F> call) {
			return add(actor, name, 6, a -> call.run(convert(a, 0, ta), convert(a, 1, tb), convert(a, 2, tc), convert(a, 3, td),
					convert(a, 4, te), convert(a, 5, tf)));
		}

		/** An action with any number of parameters (the generator uses it beyond six). */
		public Builder action(String actor, String name, int parameters, CallN call) {
			return add(actor, name, parameters, a -> call.run(new Arguments(a)));
		}

		private Builder add(String actor, String name, int arity, Entry entry) {
			ActionSchema a = schema.action(actor, name)
					.orElseThrow(() -> new IllegalArgumentException("the application has no action " + actor + "." + name));
			if (a.params().size() != arity) {
				throw new IllegalArgumentException(
						"action " + actor + "." + name + " takes " + a.params().size() + " argument(s), the method " + arity);
			}
			if (entries.put(new Key(actor, name), checkedArity(arity, entry)) != null) {
				throw new IllegalArgumentException("action " + actor + "." + name + " has two methods");
			}
			return this;
		}

		/** The table; every action of the schema must have its method. */
		public ActionTable build() {
			List<String> missing = new ArrayList<>();
			for (ActionSchema a : schema.actions()) {
				if (!entries.containsKey(new Key(a.actor(), a.name()))) {
					missing.add(a.actor() + "." + a.name());
				}
			}
			if (!missing.isEmpty()) {
				throw new IllegalStateException("no method for the actions " + missing);
			}
			return new ActionTable(entries);
		}
	}

	private static Entry checkedArity(int arity, Entry entry) {
		return a -> {
			if (a.args().size() != arity) {
				throw new IllegalArgumentException(a + " has " + a.args().size() + " argument(s), the action takes " + arity);
			}
			return entry.run(a);
		};
	}

	static <T> T convert(GroundAction action, int i, Class<T> type) {
		Object value = action.args().get(i);
		if (type == Double.class && value instanceof Number n) {
			return type.cast(n.doubleValue());
		}
		if (type.isEnum() && value instanceof EnumValue e) {
			for (T constant : type.getEnumConstants()) {
				if (((Enum<?>) constant).name().equals(e.literal())) {
					return constant;
				}
			}
		}
		if (!type.isInstance(value)) {
			throw new IllegalArgumentException("argument " + (i + 1) + " of " + action + " is not a " + type.getSimpleName() + ": "
					+ (value == null ? "null" : value + " (" + value.getClass().getName() + ")"));
		}
		return type.cast(value);
	}
}
