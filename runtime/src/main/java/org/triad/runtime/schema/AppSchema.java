package org.triad.runtime.schema;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * What the runtime needs to know of an application's models: the domain's types, the robot's and
 * the world's properties and actions, and the goals. Generated code builds one; tools build one from
 * the parsed models. Lookups are by name; iteration follows declaration order.
 */
public final class AppSchema {
	private final String name;
	private final String robot;
	private final String world;
	private final Map<String, TypeSchema> types;
	private final Map<String, PropertySchema> properties;
	private final Map<String, ActionSchema> actions;
	private final Map<String, GoalSchema> goals;
	private final Map<String, TaskSchema> tasks;

	private AppSchema(Builder b) {
		this.name = b.name;
		this.robot = b.robot;
		this.world = b.world;
		this.types = Collections.unmodifiableMap(new LinkedHashMap<>(b.types));
		this.properties = Collections.unmodifiableMap(new LinkedHashMap<>(b.properties));
		this.actions = Collections.unmodifiableMap(new LinkedHashMap<>(b.actions));
		this.goals = Collections.unmodifiableMap(new LinkedHashMap<>(b.goals));
		this.tasks = Collections.unmodifiableMap(new LinkedHashMap<>(b.tasks));
	}

	public static Builder builder(String name, String robot, String world) {
		return new Builder(name, robot, world);
	}

	public String name() {
		return name;
	}

	public String robot() {
		return robot;
	}

	public String world() {
		return world;
	}

	public Map<String, TypeSchema> types() {
		return types;
	}

	public List<PropertySchema> properties() {
		return List.copyOf(properties.values());
	}

	public List<ActionSchema> actions() {
		return List.copyOf(actions.values());
	}

	public Map<String, GoalSchema> goals() {
		return goals;
	}

	public Map<String, TaskSchema> tasks() {
		return tasks;
	}

	public Optional<TaskSchema> task(String task) {
		return Optional.ofNullable(tasks.get(task));
	}

	public Optional<PropertySchema> property(String actor, String property) {
		return Optional.ofNullable(properties.get(actor + "." + property));
	}

	/**
	 * Whether a property is a class's attribute read by the models ({@code i.weight} is the property
	 * {@code Item.weight(i)} of class Item, its "actor"): its values are the objects' own, never changed by an action.
	 */
	public boolean isAttribute(String actor, String property) {
		TypeSchema t = types.get(actor);
		return t != null && !t.isEnum() && properties.containsKey(actor + "." + property);
	}

	public Optional<ActionSchema> action(String actor, String action) {
		return Optional.ofNullable(actions.get(actor + "." + action));
	}

	public Optional<GoalSchema> goal(String goal) {
		return Optional.ofNullable(goals.get(goal));
	}

	/** Whether {@code sub} is {@code sup} or a subclass of it. */
	public boolean isSubtype(String sub, String sup) {
		String t = sub;
		int guard = types.size() + 1;
		while (t != null && guard-- > 0) {
			if (t.equals(sup)) {
				return true;
			}
			TypeSchema ts = types.get(t);
			t = ts == null ? null : ts.superType();
		}
		return false;
	}

	/** The type and its superclasses, nearest first. */
	public List<String> superTypesAndSelf(String type) {
		List<String> result = new ArrayList<>();
		String t = type;
		while (t != null && !result.contains(t)) {
			result.add(t);
			TypeSchema ts = types.get(t);
			t = ts == null ? null : ts.superType();
		}
		return result;
	}

	public static final class Builder {
		private final String name;
		private final String robot;
		private final String world;
		private final Map<String, TypeSchema> types = new LinkedHashMap<>();
		private final Map<String, PropertySchema> properties = new LinkedHashMap<>();
		private final Map<String, ActionSchema> actions = new LinkedHashMap<>();
		private final Map<String, GoalSchema> goals = new LinkedHashMap<>();
		private final Map<String, TaskSchema> tasks = new LinkedHashMap<>();

		private Builder(String name, String robot, String world) {
			this.name = name;
			this.robot = robot;
			this.world = world;
		}

		public Builder type(TypeSchema t) {
			types.put(t.name(), t);
			return this;
		}

		public Builder property(PropertySchema p) {
			properties.put(p.actor() + "." + p.name(), p);
			return this;
		}

		public Builder action(ActionSchema a) {
			actions.put(a.actor() + "." + a.name(), a);
			return this;
		}

		public Builder goal(GoalSchema g) {
			goals.put(g.name(), g);
			return this;
		}

		public Builder task(TaskSchema t) {
			tasks.put(t.name(), t);
			return this;
		}

		public AppSchema build() {
			return new AppSchema(this);
		}
	}
}
