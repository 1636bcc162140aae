package org.triad.runtime.schema;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;

import org.triad.runtime.app.Atom;
import org.triad.runtime.app.DomainObject;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.Plan;
import org.triad.runtime.app.State;

/**
 * Translates an application (its actors' properties and actions), a state and a goal into a PDDL
 * domain and problem, and plans back into actions. Boolean properties become predicates;
 * other properties predicates with a value argument whose previous value is deleted when assigned.
 * The translation stays within typed STRIPS with negative preconditions, equality and disjunction
 * (no {@code when}, no {@code exists}), so PDDL4J 3.8.3 and any STRIPS planner accept it: where a
 * property's old value is not named by the precondition, it becomes an extra action parameter.
 */
public final class PddlTranslator {
	private final AppSchema schema;

	public PddlTranslator(AppSchema schema) {
		this.schema = schema;
	}

	/** A translated planning task, with what is needed to read plans back. */
	public static final class Task {
		private final String domain;
		private final String problem;
		private final PddlNames names;
		private final Map<String, ActionSchema> actions;

		Task(String domain, String problem, PddlNames names, Map<String, ActionSchema> actions) {
			this.domain = domain;
			this.problem = problem;
			this.names = names;
			this.actions = actions;
		}

		public String domain() {
			return domain;
		}

		public String problem() {
			return problem;
		}

		PddlNames names() {
			return names;
		}

		/** A plan step read back: a PDDL action name and its arguments (extra parameters are dropped). */
		public GroundAction action(String pddlAction, List<String> pddlArgs) {
			ActionSchema a = actions.get(PddlNames.lower(pddlAction));
			if (a == null) {
				throw new PddlTranslationException("the plan has an action the application does not: " + pddlAction);
			}
			if (pddlArgs.size() < a.params().size()) {
				throw new PddlTranslationException("the plan's " + pddlAction + " has too few arguments: " + pddlArgs);
			}
			List<Object> args = new ArrayList<>();
			for (int i = 0; i < a.params().size(); i++) {
				Object v = names.valueOf(pddlArgs.get(i));
				if (v == null) {
					throw new PddlTranslationException("the plan names an unknown object: " + pddlArgs.get(i));
				}
				args.add(v);
			}
			return new GroundAction(a.actor(), a.name(), args);
		}

		public Plan plan(List<String> pddlActions, List<List<String>> pddlArgs) {
			List<GroundAction> steps = new ArrayList<>();
			for (int i = 0; i < pddlActions.size(); i++) {
				steps.add(action(pddlActions.get(i), pddlArgs.get(i)));
			}
			return new Plan(steps);
		}
	}

	/** Translates reaching {@code goal} (its parameters bound by {@code binding}) from {@code state}. */
	public Task translate(State state, GoalSchema goal, Map<String, Object> binding) {
		return translate(state, goal.condition(), binding, goal.name());
	}

	public Task translate(State state, Expr goalCondition, Map<String, Object> binding, String goalName) {
		PddlNames names = new PddlNames();
		Set<String> domainConstants = new LinkedHashSet<>();
		StringBuilder actionsText = new StringBuilder();
		Map<String, ActionSchema> actions = new LinkedHashMap<>();
		Set<String> requirements = new LinkedHashSet<>(List.of(":strips", ":typing"));
		for (ActionSchema a : schema.actions()) {
			ActionTranslation t = new ActionTranslation(a, names, domainConstants, requirements);
			actionsText.append(t.print());
			actions.put(PddlNames.action(a.actor(), a.name()), a);
		}
		// objects of the state, then values the state uses
		for (DomainObject o : state.objects().values()) {
			names.value(o, o.typeName());
		}
		StringBuilder init = new StringBuilder();
		for (Map.Entry<Atom, Object> e : state.values().entrySet()) {
			Atom atom = e.getKey();
			PropertySchema p = schema.property(atom.actor(), atom.property()).orElse(null);
			if (p == null) {
				continue; // a state may know more than the models ask about
			}
			StringBuilder fact = new StringBuilder("(").append(PddlNames.predicate(atom.actor(), atom.property()));
			for (int i = 0; i < atom.args().size(); i++) {
				fact.append(' ').append(names.value(atom.args().get(i), p.params().get(i).type()));
			}
			if (!p.isBoolean()) {
				fact.append(' ').append(names.value(e.getValue(), p.type()));
			}
			init.append("    ").append(fact).append(")\n");
		}
		GroundTranslation g = new GroundTranslation(names, binding, requirements);
		String goalText = g.formula(goalCondition);

		Set<String> types = new LinkedHashSet<>();
		StringBuilder typesText = new StringBuilder();
		for (TypeSchema t : schema.types().values()) {
			typesText.append("    ").append(PddlNames.type(t.name())).append(" - ")
					.append(t.superType() == null ? "object" : PddlNames.type(t.superType())).append('\n');
			types.add(t.name());
		}
		for (String used : usedPrimitiveTypes(names)) {
			typesText.append("    ").append(PddlNames.type(used)).append(" - object\n");
		}
		StringBuilder predicates = new StringBuilder();
		for (PropertySchema p : schema.properties()) {
			predicates.append("    (").append(PddlNames.predicate(p.actor(), p.name()));
			for (Param param : p.params()) {
				predicates.append(' ').append(PddlNames.variable(param.name())).append(" - ").append(PddlNames.type(param.type()));
			}
			if (!p.isBoolean()) {
				predicates.append(" ?value - ").append(PddlNames.type(p.type()));
			}
			predicates.append(")\n");
		}
		String domainName = PddlNames.lower(schema.name() == null ? "application" : schema.name()).replaceAll("[^a-z0-9-]", "-");
		StringBuilder domain = new StringBuilder();
		domain.append("(define (domain ").append(domainName).append(")\n");
		domain.append("  (:requirements ").append(String.join(" ", requirements)).append(")\n");
		domain.append("  (:types\n").append(typesText).append("  )\n");
		if (!domainConstants.isEmpty()) {
			domain.append("  (:constants\n");
			for (String c : domainConstants) {
				domain.append("    ").append(c).append(" - ").append(PddlNames.type(names.objectsWithTypes().get(c))).append('\n');
			}
			domain.append("  )\n");
		}
		domain.append("  (:predicates\n").append(predicates).append("  )\n");
		domain.append(actionsText);
		domain.append(")\n");

		StringBuilder problem = new StringBuilder();
		problem.append("(define (problem ").append(PddlNames.lower(goalName).replaceAll("[^a-z0-9-]", "-")).append(")\n");
		problem.append("  (:domain ").append(domainName).append(")\n");
		problem.append("  (:objects\n");
		for (Map.Entry<String, String> o : names.objectsWithTypes().entrySet()) {
			if (!domainConstants.contains(o.getKey())) {
				problem.append("    ").append(o.getKey()).append(" - ").append(PddlNames.type(o.getValue())).append('\n');
			}
		}
		problem.append("  )\n");
		problem.append("  (:init\n").append(init).append("  )\n");
		problem.append("  (:goal ").append(goalText).append(")\n");
		problem.append(")\n");
		return new Task(domain.toString(), problem.toString(), names, actions);
	}

	private static Set<String> usedPrimitiveTypes(PddlNames names) {
		Set<String> used = new LinkedHashSet<>();
		for (String t : names.objectsWithTypes().values()) {
			if (t.equals("int") || t.equals("double") || t.equals("String") || t.equals("boolean")) {
				used.add(t);
			}
		}
		return used;
	}

	/** Terms and formulas shared by action schemas (variables) and goals (objects). */
	private abstract class Formulas {
		final PddlNames names;
		final Set<String> requirements;

		Formulas(PddlNames names, Set<String> requirements) {
			this.names = names;
			this.requirements = requirements;
		}

		abstract String term(Expr e);

		String formula(Expr e) {
			if (e instanceof Expr.And) {
				List<String> parts = Exprs.conjuncts(e).stream().map(this::formula).toList();
				return parts.size() == 1 ? parts.get(0) : "(and " + String.join(" ", parts) + ")";
			}
			if (e instanceof Expr.Or o) {
				requirements.add(":disjunctive-preconditions");
				return "(or " + formula(o.left()) + " " + formula(o.right()) + ")";
			}
			if (e instanceof Expr.Not n) {
				requirements.add(":negative-preconditions");
				return "(not " + formula(n.operand()) + ")";
			}
			if (e instanceof Expr.Call c) {
				PropertySchema p = property(c);
				if (!p.isBoolean()) {
					throw new PddlTranslationException(Exprs.show(c) + " is not a condition");
				}
				return atom(c, null);
			}
			if (e instanceof Expr.Compare c) {
				if (c.op() == Expr.Op.EQ || c.op() == Expr.Op.NE) {
					String eq = equality(c.left(), c.right());
					if (c.op() == Expr.Op.NE) {
						requirements.add(":negative-preconditions");
						return "(not " + eq + ")";
					}
					return eq;
				}
				throw new PddlTranslationException("'" + c.op().symbol + "' on numbers cannot be planned with STRIPS: " + Exprs.show(c));
			}
			if (e instanceof Expr.Lit l && l.value() instanceof Boolean b) {
				return b ? "(and)" : "(or)";
			}
			throw new PddlTranslationException(Exprs.show(e) + " is not a condition");
		}

		String equality(Expr l, Expr r) {
			if (isFunction(l) && !isFunction(r)) {
				return atom((Expr.Call) l, term(r));
			}
			if (isFunction(r) && !isFunction(l)) {
				return atom((Expr.Call) r, term(l));
			}
			requirements.add(":equality");
			return "(= " + term(l) + " " + term(r) + ")";
		}

		String atom(Expr.Call c, String value) {
			StringBuilder b = new StringBuilder("(").append(PddlNames.predicate(c.actor(), c.property()));
			for (Expr a : c.args()) {
				b.append(' ').append(term(a));
			}
			if (value != null) {
				b.append(' ').append(value);
			}
			return b.append(')').toString();
		}

		boolean isFunction(Expr e) {
			return e instanceof Expr.Call c && !property(c).isBoolean();
		}

		PropertySchema property(Expr.Call c) {
			return schema.property(c.actor(), c.property())
					.orElseThrow(() -> new PddlTranslationException("unknown property " + c.actor() + "." + c.property()));
		}

		String literal(Object value, String type) {
			return names.value(value, type);
		}
	}

	/** An action schema: parameters are variables; properties read as values become extra parameters. */
	private final class ActionTranslation extends Formulas {
		private final ActionSchema action;
		private final Set<String> domainConstants;
		private final List<String> params = new ArrayList<>();
		private final Map<String, String> paramTypes = new LinkedHashMap<>();
		private final Map<String, String> valueOfCall = new LinkedHashMap<>();
		private final List<String> readPre = new ArrayList<>();
		private int fresh;

		ActionTranslation(ActionSchema action, PddlNames names, Set<String> domainConstants, Set<String> requirements) {
			super(names, requirements);
			this.action = action;
			this.domainConstants = domainConstants;
			for (Param p : action.params()) {
				params.add(PddlNames.variable(p.name()));
				paramTypes.put(PddlNames.variable(p.name()), PddlNames.type(p.type()));
			}
		}

		String print() {
			// a top-level conjunct 'f(args) == v' names f's current value, which effects may delete
			List<String> pre = new ArrayList<>();
			for (Expr c : Exprs.conjuncts(action.pre())) {
				if (c instanceof Expr.Compare cmp && cmp.op() == Expr.Op.EQ && isFunction(cmp.left()) && !isFunction(cmp.right())) {
					String v = term(cmp.right());
					valueOfCall.putIfAbsent(key((Expr.Call) cmp.left()), v);
				} else if (c instanceof Expr.Compare cmp && cmp.op() == Expr.Op.EQ && isFunction(cmp.right()) && !isFunction(cmp.left())) {
					valueOfCall.putIfAbsent(key((Expr.Call) cmp.right()), term(cmp.left()));
				}
			}
			for (Expr c : Exprs.conjuncts(action.pre())) {
				pre.add(formula(c));
			}
			List<String> effects = new ArrayList<>();
			for (Effect e : action.effects()) {
				if (e.isAssignment()) {
					String value = term(e.value());
					String old = currentValue(e.call());
					if (!old.equals(value)) {
						effects.add("(not " + atom(e.call(), old) + ")");
					}
					effects.add(atom(e.call(), value));
				} else {
					effects.add(e.holds() ? atom(e.call(), null) : "(not " + atom(e.call(), null) + ")");
				}
			}
			List<String> allPre = new ArrayList<>(readPre);
			allPre.addAll(pre);
			StringBuilder b = new StringBuilder();
			b.append("  (:action ").append(PddlNames.action(action.actor(), action.name())).append('\n');
			b.append("    :parameters (").append(params.stream().map(p -> p + " - " + paramTypes.get(p)).collect(Collectors.joining(" ")))
					.append(")\n");
			b.append("    :precondition ").append(allPre.isEmpty() ? "(and)" : "(and " + String.join(" ", allPre) + ")").append('\n');
			b.append("    :effect ").append(effects.isEmpty() ? "(and)" : "(and " + String.join(" ", effects) + ")").append(")\n");
			return b.toString();
		}

		/** The term for the value a function call has before the action, binding a fresh parameter if needed. */
		private String currentValue(Expr.Call call) {
			String key = key(call);
			String known = valueOfCall.get(key);
			if (known != null) {
				return known;
			}
			String v = "?" + PddlNames.lower(call.property()) + "-" + (++fresh);
			params.add(v);
			paramTypes.put(v, PddlNames.type(property(call).type()));
			valueOfCall.put(key, v);
			readPre.add(atom(call, v));
			return v;
		}

		private String key(Expr.Call call) {
			StringBuilder b = new StringBuilder(PddlNames.predicate(call.actor(), call.property()));
			for (Expr a : call.args()) {
				b.append(' ').append(term(a));
			}
			return b.toString();
		}

		@Override
		String term(Expr e) {
			if (e instanceof Expr.Var v) {
				String name = PddlNames.variable(v.name());
				if (!paramTypes.containsKey(name)) {
					throw new PddlTranslationException("action " + action.name() + " uses '" + v.name() + "', which is not a parameter");
				}
				return name;
			}
			if (e instanceof Expr.Call c && !property(c).isBoolean()) {
				return currentValue(c);
			}
			String constant;
			if (e instanceof Expr.Lit l) {
				constant = literal(l.value(), null);
			} else if (e instanceof Expr.EnumLit l) {
				constant = literal(new org.triad.runtime.app.EnumValue(l.enumeration(), l.literal()), l.enumeration());
			} else {
				throw new PddlTranslationException(Exprs.show(e) + " is not a value");
			}
			domainConstants.add(constant);
			return constant;
		}
	}

	/** A goal: parameters are bound to objects, so terms are object names. */
	private final class GroundTranslation extends Formulas {
		private final Map<String, Object> binding;

		GroundTranslation(PddlNames names, Map<String, Object> binding, Set<String> requirements) {
			super(names, requirements);
			this.binding = binding;
		}

		@Override
		String term(Expr e) {
			if (e instanceof Expr.Var v) {
				Object value = binding.get(v.name());
				if (value == null) {
					Object o = names.valueOf(v.name());
					if (o == null) {
						throw new PddlTranslationException("the goal uses '" + v.name() + "', which is neither bound nor an object");
					}
					return PddlNames.lower(v.name());
				}
				return literal(value, null);
			}
			if (e instanceof Expr.Lit l) {
				return literal(l.value(), null);
			}
			if (e instanceof Expr.EnumLit l) {
				return literal(new org.triad.runtime.app.EnumValue(l.enumeration(), l.literal()), l.enumeration());
			}
			throw new PddlTranslationException("the goal compares " + Exprs.show(e)
					+ " with another property; only comparisons with objects or literals can be planned");
		}
	}
}
