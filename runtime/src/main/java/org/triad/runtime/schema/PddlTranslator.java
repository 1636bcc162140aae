package org.triad.runtime.schema;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.triad.runtime.app.Atom;
import org.triad.runtime.app.DomainObject;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.Plan;
import org.triad.runtime.app.State;
import org.triad.planner.pddl.Action;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.Formula;
import org.triad.planner.pddl.NumericExpr;
import org.triad.planner.pddl.NumericTerm;
import org.triad.planner.pddl.PddlEffect;
import org.triad.planner.pddl.PddlWriter;
import org.triad.planner.pddl.PredicateDecl;
import org.triad.planner.pddl.Problem;
import org.triad.planner.pddl.TypedName;

/**
 * Translates an application (its actors' properties and actions), a state and a goal into a PDDL
 * domain and problem (the planner's typed model: no text on the way to Triad's engine; text only for
 * {@code triad pddl} and planners outside the JVM), and plans back into actions. Boolean properties become predicates;
 * other properties predicates with a value argument whose previous value is deleted when assigned.
 * The translation stays within typed STRIPS with negative preconditions, equality and disjunction
 * (no {@code when}, no {@code exists}), so PDDL4J 3.8.3 and any STRIPS planner accept it: where a
 * property's old value is not named by the precondition, it becomes an extra action parameter.
 */
public final class PddlTranslator {
	/** The marker actions and predicates of a sequence of goals ({@link #translateSequence}). */
	static final String REACHED = "triad-reached-";

	/** The metric's accumulator: every action adds its cost. */
	static final String TOTAL_COST = "total-cost";

	private final AppSchema schema;
	private final Quantities quantities;
	private final boolean costed;

	/** Whether the application has quantities, numbers the planner computes with (a battery, a load, a distance). */
	public boolean plansQuantities() {
		return quantities.any();
	}

	/**
	 * Whether an action changes a quantity (a battery, a load), so that reaching a goal can use up what the next
	 * goal needs; distances only charged as a cost cannot.
	 */
	public boolean changesQuantities() {
		return quantities.anyChanged();
	}

	/** Whether a property is a quantity. */
	public boolean isQuantity(String actor, String property) {
		return quantities.isQuantity(actor, property);
	}

	public PddlTranslator(AppSchema schema) {
		this.schema = schema;
		this.quantities = new Quantities(schema);
		this.costed = schema.actions().stream().anyMatch(a -> a.cost() != null);
	}

	/** A translated planning task, with what is needed to read plans back. */
	public static final class Task {
		private final Domain domain;
		private final Problem problem;
		private final PddlNames names;
		private final Map<String, ActionSchema> actions;

		Task(Domain domain, Problem problem, PddlNames names, Map<String, ActionSchema> actions) {
			this.domain = domain;
			this.problem = problem;
			this.names = names;
			this.actions = actions;
		}

		/** The domain as the planner takes it. */
		public Domain domain() {
			return domain;
		}

		/** The problem as the planner takes it. */
		public Problem problem() {
			return problem;
		}

		/** The domain as PDDL text, for {@code triad pddl} and planners outside the JVM. */
		public String domainText() {
			return PddlWriter.write(domain);
		}

		/** The problem as PDDL text. */
		public String problemText() {
			return PddlWriter.write(problem);
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

		/** The steps of a plan for a sequence of goals up to the marker of the first goal, read back. */
		public Plan planUntilReached(List<String> pddlActions, List<List<String>> pddlArgs) {
			List<GroundAction> steps = new ArrayList<>();
			for (int i = 0; i < pddlActions.size(); i++) {
				if (PddlNames.lower(pddlActions.get(i)).startsWith(REACHED)) {
					break;
				}
				steps.add(action(pddlActions.get(i), pddlArgs.get(i)));
			}
			return new Plan(steps);
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
		return translate(state, List.of(new Stage(goalCondition, binding)), goalName);
	}

	/** One goal of a sequence: its condition and the values of its parameters. */
	public record Stage(Expr condition, Map<String, Object> binding) {
	}

	/**
	 * Translates reaching the goals in order, each holding at some instant after the one before (a task's
	 * remaining goals, planned as one lookahead): a marker action {@code triad-reached-k} may run once goal k
	 * holds and goal k-1 was reached, and the problem's goal is the last marker. {@link Task#planUntilReached}
	 * reads back the part of the plan that reaches the first goal.
	 */
	public Task translateSequence(State state, List<Stage> stages, String name) {
		return translate(state, stages, name);
	}

	private Task translate(State state, List<Stage> stages, String goalName) {
		if (stages.isEmpty()) {
			throw new IllegalArgumentException("no goal to translate");
		}
		PddlNames names = new PddlNames();
		Set<String> domainConstants = new LinkedHashSet<>();
		List<Action> pddlActions = new ArrayList<>();
		Map<String, ActionSchema> actions = new LinkedHashMap<>();
		Set<String> requirements = new LinkedHashSet<>(List.of(":strips", ":typing"));
		NumberOrder order = new NumberOrder();
		for (ActionSchema a : schema.actions()) {
			pddlActions.add(new ActionTranslation(a, names, domainConstants, requirements, order).action());
			actions.put(PddlNames.action(a.actor(), a.name()), a);
		}
		// objects of the state, then values the state uses
		for (DomainObject o : state.objects().values()) {
			names.value(o, o.typeName());
		}
		List<Formula.Atom> init = new ArrayList<>();
		List<Problem.NumericFact> numericInit = new ArrayList<>();
		for (Map.Entry<Atom, Object> e : withAttributes(state).entrySet()) {
			Atom atom = e.getKey();
			PropertySchema p = schema.property(atom.actor(), atom.property()).orElse(null);
			if (p == null) {
				continue; // a state may know more than the models ask about
			}
			List<String> args = new ArrayList<>();
			for (int i = 0; i < atom.args().size(); i++) {
				args.add(names.value(atom.args().get(i), p.params().get(i).type()));
			}
			if (quantities.isQuantity(atom.actor(), atom.property())) {
				if (!(e.getValue() instanceof Number n) || !Double.isFinite(n.doubleValue())) {
					throw new PddlTranslationException(atom.actor() + "." + atom.property() + "(" + atom.args().stream().map(String::valueOf)
							.collect(java.util.stream.Collectors.joining(", ")) + ") is " + e.getValue() + " in the state: a quantity the planner computes with must be a finite number");
				}
				numericInit.add(new Problem.NumericFact(PddlNames.predicate(atom.actor(), atom.property()), args, n.doubleValue()));
				continue;
			}
			if (!p.isBoolean()) {
				args.add(names.value(e.getValue(), p.type()));
			}
			init.add(new Formula.Atom(PddlNames.predicate(atom.actor(), atom.property()), args));
		}
		Formula goal;
		List<PredicateDecl> markers = new ArrayList<>();
		if (stages.size() == 1) {
			goal = new GroundTranslation(names, stages.get(0).binding(), requirements, order).formula(stages.get(0).condition());
		} else {
			for (int k = 1; k <= stages.size(); k++) {
				Stage stage = stages.get(k - 1);
				Formula reached = new GroundTranslation(names, stage.binding(), requirements, order).formula(stage.condition());
				List<Formula> pre = new ArrayList<>();
				if (k > 1) {
					pre.add(Formula.Atom.of(REACHED + (k - 1)));
				}
				pre.add(reached);
				markers.add(new PredicateDecl(REACHED + k, List.of()));
				pddlActions.add(new Action(REACHED + k, List.of(), new Formula.And(pre), List.of(new PddlEffect.Add(Formula.Atom.of(REACHED + k)))));
			}
			goal = Formula.Atom.of(REACHED + stages.size());
		}
		if (order.used()) {
			init.addAll(order.facts(names));
		}

		List<TypedName> types = new ArrayList<>();
		for (TypeSchema t : schema.types().values()) {
			types.add(TypedName.of(PddlNames.type(t.name()), t.superType() == null ? "object" : PddlNames.type(t.superType())));
		}
		for (String used : usedPrimitiveTypes(names)) {
			types.add(TypedName.of(PddlNames.type(used), "object"));
		}
		List<PredicateDecl> predicates = new ArrayList<>();
		List<PredicateDecl> functions = new ArrayList<>();
		for (PropertySchema p : schema.properties()) {
			List<TypedName> params = new ArrayList<>();
			for (Param param : p.params()) {
				params.add(TypedName.of(PddlNames.variable(param.name()), PddlNames.type(param.type())));
			}
			if (quantities.isQuantity(p.actor(), p.name())) {
				functions.add(new PredicateDecl(PddlNames.predicate(p.actor(), p.name()), params));
				continue;
			}
			if (!p.isBoolean()) {
				params.add(TypedName.of("?value", PddlNames.type(p.type())));
			}
			predicates.add(new PredicateDecl(PddlNames.predicate(p.actor(), p.name()), params));
		}
		if (order.used()) {
			predicates.addAll(order.predicates());
		}
		predicates.addAll(markers);
		List<TypedName> constants = new ArrayList<>();
		for (String c : domainConstants) {
			constants.add(TypedName.of(c, PddlNames.type(names.objectsWithTypes().get(c))));
		}
		List<TypedName> objects = new ArrayList<>();
		for (Map.Entry<String, String> o : names.objectsWithTypes().entrySet()) {
			if (!domainConstants.contains(o.getKey())) {
				objects.add(TypedName.of(o.getKey(), PddlNames.type(o.getValue())));
			}
		}
		String domainName = PddlNames.lower(schema.name() == null ? "application" : schema.name()).replaceAll("[^a-z0-9-]", "-");
		String metric = null;
		if (costed) {
			functions.add(new PredicateDecl(TOTAL_COST, List.of()));
			numericInit.add(new Problem.NumericFact(TOTAL_COST, List.of(), 0));
			metric = "minimize (" + TOTAL_COST + ")";
		}
		if (!functions.isEmpty()) {
			requirements.add(":fluents"); // what Metric-FF reads (it does not know ':numeric-fluents'); VAL and Triad's engine read both
		}
		Domain domain = new Domain(domainName, List.copyOf(requirements), types, constants, predicates, functions, pddlActions);
		Problem problem = new Problem(PddlNames.lower(goalName).replaceAll("[^a-z0-9-]", "-"), domainName, objects, init, numericInit, goal,
				metric);
		return new Task(domain, problem, names, actions);
	}

	/**
	 * The state's values, and the values of the attributes the models read ({@code i.weight}) taken from the objects
	 * themselves where the state does not state them. A quantity's attribute must have a value: a planner cannot
	 * compute with a number it does not know.
	 */
	private Map<Atom, Object> withAttributes(State state) {
		Map<Atom, Object> values = new LinkedHashMap<>(state.values());
		for (PropertySchema p : schema.properties()) {
			if (!schema.isAttribute(p.actor(), p.name())) {
				continue;
			}
			for (DomainObject o : state.objects().values()) {
				if (!schema.isSubtype(o.typeName(), p.actor())) {
					continue;
				}
				Atom atom = new Atom(p.actor(), p.name(), List.of(o));
				if (values.containsKey(atom)) {
					continue;
				}
				Object value = o.attribute(p.name());
				if (value == null && quantities.isQuantity(p.actor(), p.name())) {
					throw new PddlTranslationException(o.typeName() + " " + o.name() + " has no " + p.name() + ", an attribute of " + p.actor()
							+ " the models compute with: give it one, e.g. '" + o.typeName() + " " + o.name() + " { " + p.name() + " = ...; };'");
				}
				if (value != null) {
					values.put(atom, org.triad.runtime.app.Values.canonical(value));
				}
			}
		}
		return values;
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
		final NumberOrder order;

		Formulas(PddlNames names, Set<String> requirements, NumberOrder order) {
			this.names = names;
			this.requirements = requirements;
			this.order = order;
		}

		abstract String term(Expr e);

		/** {@code <}, {@code <=}, {@code >} or {@code >=} on numbers. */
		abstract Formula ordering(Expr.Compare c);

		Formula formula(Expr e) {
			if (e instanceof Expr.And) {
				List<Formula> parts = Exprs.conjuncts(e).stream().map(this::formula).toList();
				return parts.size() == 1 ? parts.get(0) : new Formula.And(parts);
			}
			if (e instanceof Expr.Or o) {
				requirements.add(":disjunctive-preconditions");
				return new Formula.Or(List.of(formula(o.left()), formula(o.right())));
			}
			if (e instanceof Expr.Not n) {
				requirements.add(":negative-preconditions");
				return new Formula.Not(formula(n.operand()));
			}
			if (e instanceof Expr.Call c) {
				PropertySchema p = property(c);
				if (!p.isBoolean()) {
					throw new PddlTranslationException(Exprs.show(c) + " is not a condition");
				}
				return atom(c, null);
			}
			if (e instanceof Expr.Compare c) {
				if (isNumericComparison(c)) {
					return numericComparison(c);
				}
				if (c.op() == Expr.Op.EQ || c.op() == Expr.Op.NE) {
					Formula eq = equality(c.left(), c.right());
					if (c.op() == Expr.Op.NE) {
						requirements.add(":negative-preconditions");
						return new Formula.Not(eq);
					}
					return eq;
				}
				return ordering(c);
			}
			if (e instanceof Expr.Lit l && l.value() instanceof Boolean b) {
				return b ? new Formula.And(List.of()) : new Formula.Or(List.of());
			}
			if (e instanceof Expr.Var) {
				return truth(e); // a boolean parameter as a condition
			}
			throw new PddlTranslationException(Exprs.show(e) + " is not a condition");
		}

		Formula equality(Expr l, Expr r) {
			if (isCondition(l) || isCondition(r)) {
				// 'p() == false', 'p() == q()': the same truth value
				requirements.add(":negative-preconditions");
				requirements.add(":disjunctive-preconditions");
				Formula a = truth(l);
				Formula b = truth(r);
				return new Formula.Or(List.of(new Formula.And(List.of(a, b)), new Formula.And(List.of(new Formula.Not(a), new Formula.Not(b)))));
			}
			if (isFunction(l) && !isFunction(r)) {
				return atom((Expr.Call) l, term(r));
			}
			if (isFunction(r) && !isFunction(l)) {
				return atom((Expr.Call) r, term(l));
			}
			requirements.add(":equality");
			return new Formula.Equals(term(l), term(r));
		}

		Formula.Atom atom(Expr.Call c, String value) {
			List<String> args = new ArrayList<>();
			for (Expr a : c.args()) {
				args.add(term(a));
			}
			if (value != null) {
				args.add(value);
			}
			return new Formula.Atom(PddlNames.predicate(c.actor(), c.property()), args);
		}

		private boolean isCondition(Expr e) {
			return e instanceof Expr.Call c && property(c).isBoolean();
		}

		/** A Boolean operand of '==' as a formula: a condition as it is, a Boolean value as equal to true. */
		private Formula truth(Expr e) {
			if (isCondition(e) || e instanceof Expr.Lit l && l.value() instanceof Boolean) {
				return formula(e);
			}
			requirements.add(":equality");
			return new Formula.Equals(term(e), term(new Expr.Lit(Boolean.TRUE)));
		}

		/** A non-Boolean property read as a value (an argument of its predicate); quantities are numeric fluents instead. */
		boolean isFunction(Expr e) {
			return e instanceof Expr.Call c && !property(c).isBoolean() && !quantities.isQuantity(c);
		}

		/** A comparison the planner computes: one side is arithmetic or reads a quantity. */
		boolean isNumericComparison(Expr.Compare c) {
			return quantities.isNumericTerm(c.left()) || quantities.isNumericTerm(c.right());
		}

		Formula numericComparison(Expr.Compare c) {
			requirements.add(":fluents");
			NumericExpr l = numeric(c.left());
			NumericExpr r = numeric(c.right());
			return switch (c.op()) {
				case EQ -> new Formula.Compare("=", l, r);
				case NE -> {
					requirements.add(":negative-preconditions");
					yield new Formula.Not(new Formula.Compare("=", l, r));
				}
				case LT -> new Formula.Compare("<", l, r);
				case LE -> new Formula.Compare("<=", l, r);
				case GT -> new Formula.Compare(">", l, r);
				case GE -> new Formula.Compare(">=", l, r);
			};
		}

		/** A number the planner computes with: a literal, a quantity, arithmetic on them, or (in a goal) a bound number. */
		NumericExpr numeric(Expr e) {
			if (e instanceof Expr.Arith a) {
				return new NumericExpr.Arithmetic(a.op(), numeric(a.left()), numeric(a.right()));
			}
			if (e instanceof Expr.Call c && quantities.isQuantity(c)) {
				List<String> args = new ArrayList<>();
				for (Expr arg : c.args()) {
					args.add(term(arg));
				}
				return new NumericExpr.Fluent(PddlNames.predicate(c.actor(), c.property()), args);
			}
			Object v = number(e);
			if (v instanceof Number n && Double.isFinite(n.doubleValue())) {
				return new NumericExpr.Number(n.doubleValue());
			}
			throw new PddlTranslationException(Exprs.show(e) + " cannot be computed with by the planner: a quantity is compared or combined with"
					+ " literals, bound goal arguments and other quantities only" + (v == null ? "" : " (it is " + v + ")"));
		}

		/** The number an operand stands for before planning (a literal, or a bound goal argument), or null. */
		Object number(Expr e) {
			return e instanceof Expr.Lit l ? l.value() : null;
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
		private final List<Formula> readPre = new ArrayList<>();
		private int fresh;

		ActionTranslation(ActionSchema action, PddlNames names, Set<String> domainConstants, Set<String> requirements,
				NumberOrder order) {
			super(names, requirements, order);
			this.action = action;
			this.domainConstants = domainConstants;
			for (Param p : action.params()) {
				params.add(PddlNames.variable(p.name()));
				paramTypes.put(PddlNames.variable(p.name()), PddlNames.type(p.type()));
			}
		}

		Action action() {
			// a top-level conjunct 'f(args) == v' names f's current value, which effects may delete
			for (Expr c : Exprs.conjuncts(action.pre())) {
				if (c instanceof Expr.Compare cmp && cmp.op() == Expr.Op.EQ && isFunction(cmp.left()) && !isFunction(cmp.right())) {
					String v = term(cmp.right());
					valueOfCall.putIfAbsent(key((Expr.Call) cmp.left()), v);
				} else if (c instanceof Expr.Compare cmp && cmp.op() == Expr.Op.EQ && isFunction(cmp.right()) && !isFunction(cmp.left())) {
					valueOfCall.putIfAbsent(key((Expr.Call) cmp.right()), term(cmp.left()));
				}
			}
			List<Formula> pre = new ArrayList<>();
			for (Expr c : Exprs.conjuncts(action.pre())) {
				pre.add(formula(c));
			}
			List<PddlEffect> effects = new ArrayList<>();
			for (Effect e : action.effects()) {
				if (e.isAssignment() && quantities.isQuantity(e.call())) {
					effects.add(numericEffect(e));
				} else if (e.isAssignment()) {
					String value = term(e.value());
					String old = currentValue(e.call());
					if (!old.equals(value)) {
						effects.add(new PddlEffect.Delete(atom(e.call(), old)));
					}
					effects.add(new PddlEffect.Add(atom(e.call(), value)));
				} else {
					effects.add(e.holds() ? new PddlEffect.Add(atom(e.call(), null)) : new PddlEffect.Delete(atom(e.call(), null)));
				}
			}
			if (action.cost() != null) {
				effects.add(cost(numeric(action.cost())));
			}
			List<Formula> allPre = new ArrayList<>(readPre);
			allPre.addAll(pre);
			List<TypedName> parameters = params.stream().map(p -> TypedName.of(p, paramTypes.get(p))).toList();
			return new Action(PddlNames.action(action.actor(), action.name()), parameters, new Formula.And(allPre), effects);
		}

		/**
		 * {@code f == f@pre + x} is {@code (increase f x)}, {@code f == f@pre - x} {@code (decrease f x)}, as
		 * Metric-FF's numeric relaxed planning graph reads them best; any other value {@code (assign f v)}.
		 */
		private PddlEffect numericEffect(Effect e) {
			requirements.add(":fluents");
			NumericExpr.Fluent target = (NumericExpr.Fluent) numeric(e.call());
			NumericExpr value = numeric(e.value());
			if (value instanceof NumericExpr.Arithmetic a && (a.op() == '+' || a.op() == '-') && a.left().equals(target)) {
				return new PddlEffect.NumericEffect(a.op() == '+' ? "increase" : "decrease", target, a.right());
			}
			if (value instanceof NumericExpr.Arithmetic a && a.op() == '+' && a.right().equals(target)) {
				return new PddlEffect.NumericEffect("increase", target, a.left());
			}
			return new PddlEffect.NumericEffect("assign", target, value);
		}

		/** The action's cost added to the metric: a number or one fluent as PDDL's action costs write it, else any expression. */
		private PddlEffect cost(NumericExpr amount) {
			if (amount instanceof NumericExpr.Number n) {
				return new PddlEffect.Increase(TOTAL_COST, new NumericTerm.Constant(n.value()));
			}
			if (amount instanceof NumericExpr.Fluent f) {
				return new PddlEffect.Increase(TOTAL_COST, new NumericTerm.Function(f.name(), f.args()));
			}
			return new PddlEffect.NumericEffect("increase", NumericExpr.Fluent.of(TOTAL_COST), amount);
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
			return PddlWriter.atom(atom(call, null));
		}

		@Override
		Formula ordering(Expr.Compare c) {
			return order.atom(c.op(), term(c.left()), term(c.right()));
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

		GroundTranslation(PddlNames names, Map<String, Object> binding, Set<String> requirements, NumberOrder order) {
			super(names, requirements, order);
			this.binding = binding;
		}

		/**
		 * A goal has no parameters to name a property's current value, so a condition that reads a
		 * non-Boolean property other than as {@code f(objects) == value} (an ordering, two properties
		 * compared, a property as an argument) becomes a disjunction over the values the property can
		 * have: every object or number of its type the translation names.
		 */
		@Override
		Formula formula(Expr e) {
			if (e instanceof Expr.Compare || e instanceof Expr.Call) {
				Expr.Call read = readInside(e);
				if (read != null) {
					List<Formula> cases = new ArrayList<>();
					for (Object value : candidates(property(read).type())) {
						Formula rest = formula(replace(e, read, new Expr.Lit(value)));
						// a case decided false now is left out, one decided true is the read alone: Metric-FF and
						// VAL do not read an empty (and) or (or)
						if (rest instanceof Formula.Or or && or.parts().isEmpty()) {
							continue;
						}
						Formula is = atom(read, literal(value, null));
						cases.add(rest instanceof Formula.And and && and.parts().isEmpty() ? is : new Formula.And(List.of(is, rest)));
					}
					if (cases.isEmpty()) {
						return new Formula.Or(List.of());
					}
					requirements.add(":disjunctive-preconditions");
					return cases.size() == 1 ? cases.get(0) : new Formula.Or(cases);
				}
			}
			return super.formula(e);
		}

		/** The innermost property read that {@link Formulas#formula} cannot translate directly, or null. */
		private Expr.Call readInside(Expr e) {
			if (e instanceof Expr.Call c) {
				return innermostIn(c.args());
			}
			Expr.Compare c = (Expr.Compare) e;
			if (c.op() != Expr.Op.EQ && c.op() != Expr.Op.NE || isFunction(c.left()) && isFunction(c.right())) {
				Expr.Call left = innermost(c.left());
				return left != null ? left : innermost(c.right());
			}
			for (Expr side : List.of(c.left(), c.right())) {
				if (side instanceof Expr.Call call) {
					Expr.Call inner = innermostIn(call.args());
					if (inner != null) {
						return inner;
					}
				}
			}
			return null;
		}

		private Expr.Call innermostIn(List<Expr> args) {
			for (Expr a : args) {
				Expr.Call found = innermost(a);
				if (found != null) {
					return found;
				}
			}
			return null;
		}

		private Expr.Call innermost(Expr e) {
			if (!(e instanceof Expr.Call c)) {
				return null;
			}
			Expr.Call inner = innermostIn(c.args());
			return inner != null ? inner : isFunction(c) ? c : null;
		}

		private Expr replace(Expr e, Expr.Call read, Expr value) {
			if (e.equals(read)) {
				return value;
			}
			if (e instanceof Expr.Call c) {
				return new Expr.Call(c.actor(), c.property(), c.args().stream().map(a -> replace(a, read, value)).toList());
			}
			if (e instanceof Expr.Compare c) {
				return new Expr.Compare(c.op(), replace(c.left(), read, value), replace(c.right(), read, value));
			}
			return e;
		}

		/** The values a property of {@code type} can have: the objects and numbers of that type named so far. */
		private List<Object> candidates(String type) {
			boolean numeric = type.equals("int") || type.equals("double");
			List<Object> values = new ArrayList<>();
			for (Map.Entry<String, String> o : List.copyOf(names.objectsWithTypes().entrySet())) {
				Object v = names.valueOf(o.getKey());
				// a number of the property's own type: an int constant is not a value of a double property in PDDL
				if (numeric ? v instanceof Number && o.getValue().equals(type) : schema.isSubtype(o.getValue(), type)) {
					values.add(v);
				}
			}
			return values;
		}

		/** Both sides are values here (property reads were expanded): the comparison is decided now. */
		@Override
		Formula ordering(Expr.Compare c) {
			Object l = value(c.left());
			Object r = value(c.right());
			boolean holds = l instanceof Number a && r instanceof Number b && NumberOrder.holds(c.op(), a.doubleValue(), b.doubleValue());
			return holds ? new Formula.And(List.of()) : new Formula.Or(List.of());
		}

		@Override
		Object number(Expr e) {
			return value(e);
		}

		private Object value(Expr e) {
			if (e instanceof Expr.Var v) {
				Object bound = binding.get(v.name());
				return bound != null ? org.triad.runtime.app.Values.canonical(bound) : names.valueOf(v.name());
			}
			return e instanceof Expr.Lit l ? l.value() : null;
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
