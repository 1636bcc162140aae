package org.triad.generator;

import java.util.ArrayList;
import java.util.List;

import org.triad.dsl.semantics.Postconditions;
import org.triad.dsl.triad.Action;
import org.triad.dsl.triad.Actor;
import org.triad.dsl.triad.BinaryExpression;
import org.triad.dsl.triad.BooleanLiteral;
import org.triad.dsl.triad.DecimalLiteral;
import org.triad.dsl.triad.DomainClass;
import org.triad.dsl.triad.DomainType;
import org.triad.dsl.triad.EnumLiteral;
import org.triad.dsl.triad.MemberRef;
import org.triad.dsl.triad.Attribute;
import org.triad.dsl.triad.Enumeration;
import org.triad.dsl.triad.Expression;
import org.triad.dsl.triad.Goal;
import org.triad.dsl.triad.GoalReference;
import org.triad.dsl.triad.Task;
import org.triad.dsl.triad.IntLiteral;
import org.triad.dsl.triad.NotExpression;
import org.triad.dsl.triad.Parameter;
import org.triad.dsl.triad.Property;
import org.triad.dsl.triad.PropertyCall;
import org.triad.dsl.triad.StringLiteral;
import org.triad.dsl.triad.ValueRef;
import org.triad.dsl.triad.Application;
import org.triad.dsl.typing.TriadTypeSystem;
import org.triad.runtime.schema.ActionSchema;
import org.triad.runtime.schema.AppSchema;
import org.triad.runtime.schema.Effect;
import org.triad.runtime.schema.Expr;
import org.triad.runtime.schema.GoalSchema;
import org.triad.runtime.schema.Param;
import org.triad.runtime.schema.PropertySchema;
import org.triad.runtime.schema.TaskSchema;
import org.triad.runtime.schema.TypeSchema;

/**
 * Turns a checked application model into the runtime's {@link AppSchema}: the one place where the
 * modeling languages' meaning is handed to the runtime, used by the CLI directly and by the code
 * generator, which prints code that rebuilds the same schema.
 */
public final class SchemaBuilder {
	private SchemaBuilder() {
	}

	public static AppSchema build(Application app) {
		Actor robot = app.getRobot();
		Actor world = app.getWorld();
		AppSchema.Builder b = AppSchema.builder(app.getName(), robot == null ? null : robot.getName(), world == null ? null : world.getName());
		if (app.getDomain() != null) {
			for (DomainType t : app.getDomain().getTypes()) {
				if (t instanceof Enumeration e) {
					b.type(TypeSchema.ofEnum(e.getName(), e.getLiterals().stream().map(EnumLiteral::getName).toList()));
				} else if (t instanceof DomainClass c) {
					b.type(TypeSchema.ofClass(c.getName(), c.getSuperType() == null ? null : c.getSuperType().getName(), c.isAbstract()));
				}
			}
		}
		// an attribute the models read (i.weight) is a property of its class, whose values are the objects' own
		for (Attribute a : readAttributes(app)) {
			DomainClass c = (DomainClass) a.eContainer();
			b.property(new PropertySchema(c.getName(), a.getName(), List.of(new Param("o", c.getName())), TriadTypeSystem.typeOf(a.getType()).display()));
		}
		for (Actor actor : actors(app)) {
			for (Property p : actor.getProperties()) {
				b.property(new PropertySchema(actor.getName(), p.getName(), params(p.getParameters()),
						TriadTypeSystem.typeOf(p.getType()).display()));
			}
			for (Action a : actor.getActions()) {
				List<Effect> effects = new ArrayList<>();
				for (org.triad.dsl.semantics.PostconditionEffect e : Postconditions.analyse(a.getPost()).effects()) {
					effects.add(new Effect((Expr.Call) expr(e.call()), e.holds(), e.value() == null ? null : expr(e.value())));
				}
				b.action(new ActionSchema(actor.getName(), a.getName(), params(a.getParameters()),
						a.getPre() == null ? Expr.TRUE : expr(a.getPre()), effects, a.getCost() == null ? null : expr(a.getCost())));
			}
		}
		for (Goal g : app.getGoals()) {
			b.goal(new GoalSchema(g.getName(), params(g.getParameters()), g.getCondition() == null ? Expr.TRUE : expr(g.getCondition())));
		}
		for (Task t : app.getTasks()) {
			List<TaskSchema.Step> steps = new ArrayList<>();
			for (GoalReference ref : t.getSteps()) {
				steps.add(new TaskSchema.Step(ref.getGoal().getName(), ref.getArguments().stream().map(SchemaBuilder::expr).toList()));
			}
			b.task(new TaskSchema(t.getName(), params(t.getParameters()), steps));
		}
		return b.build();
	}

	/** The attributes read in the actors', goals' and tasks' expressions, in the order of the class diagram. */
	private static List<Attribute> readAttributes(Application app) {
		java.util.Set<Attribute> read = new java.util.HashSet<>();
		List<org.eclipse.emf.ecore.EObject> roots = new ArrayList<>(actors(app));
		roots.addAll(app.getGoals());
		roots.addAll(app.getTasks());
		for (org.eclipse.emf.ecore.EObject root : roots) {
			for (MemberRef r : org.eclipse.xtext.EcoreUtil2.getAllContentsOfType(root, MemberRef.class)) {
				if (r.getMember() instanceof Attribute a && !a.eIsProxy()) {
					read.add(a);
				}
			}
		}
		List<Attribute> ordered = new ArrayList<>();
		if (app.getDomain() != null) {
			for (DomainType t : app.getDomain().getTypes()) {
				if (t instanceof DomainClass c) {
					c.getAttributes().stream().filter(read::contains).forEach(ordered::add);
				}
			}
		}
		return ordered;
	}

	private static List<Actor> actors(Application app) {
		List<Actor> actors = new ArrayList<>();
		if (app.getRobot() != null) {
			actors.add(app.getRobot());
		}
		if (app.getWorld() != null) {
			actors.add(app.getWorld());
		}
		return actors;
	}

	static List<Param> params(List<Parameter> ps) {
		return ps.stream().map(p -> new Param(p.getName(), TriadTypeSystem.typeOf(p.getType()).display())).toList();
	}

	/** The runtime form of a model expression; unqualified property calls name their enclosing actor. */
	public static Expr expr(Expression e) {
		if (e instanceof BinaryExpression b) {
			Expr l = expr(b.getLeft());
			Expr r = expr(b.getRight());
			return switch (b.getOperator()) {
				case AND -> new Expr.And(l, r);
				case OR -> new Expr.Or(l, r);
				case EQ -> new Expr.Compare(Expr.Op.EQ, l, r);
				case NE -> new Expr.Compare(Expr.Op.NE, l, r);
				case LT -> new Expr.Compare(Expr.Op.LT, l, r);
				case LE -> new Expr.Compare(Expr.Op.LE, l, r);
				case GT -> new Expr.Compare(Expr.Op.GT, l, r);
				case GE -> new Expr.Compare(Expr.Op.GE, l, r);
				case PLUS -> new Expr.Arith('+', l, r);
				case MINUS -> new Expr.Arith('-', l, r);
				case TIMES -> new Expr.Arith('*', l, r);
				case DIVIDE -> new Expr.Arith('/', l, r);
			};
		}
		if (e instanceof NotExpression n) {
			return new Expr.Not(expr(n.getOperand()));
		}
		if (e instanceof org.triad.dsl.triad.NegationExpression n) {
			// a negative literal is a value (an attribute, a fact's argument); any other negation is '0 - x', which the
			// planner's arithmetic already computes
			if (n.getOperand() instanceof IntLiteral l) {
				return new Expr.Lit(-l.getValue());
			}
			if (n.getOperand() instanceof DecimalLiteral l) {
				return new Expr.Lit(-l.getValue());
			}
			boolean integral = TriadTypeSystem.typeOf(n.getOperand()).kind() == org.triad.dsl.typing.TriadType.Kind.INT;
			return new Expr.Arith('-', new Expr.Lit(integral ? (Object) 0 : (Object) 0.0), expr(n.getOperand()));
		}
		if (e instanceof PropertyCall c) {
			// 'p()@pre' needs no mark of its own: the runtime evaluates every effect's value in the state before the action
			Actor actor = c.getActor() != null ? c.getActor() : org.eclipse.xtext.EcoreUtil2.getContainerOfType(c, Actor.class);
			return new Expr.Call(actor.getName(), c.getProperty().getName(), c.getArguments().stream().map(SchemaBuilder::expr).toList());
		}
		if (e instanceof ValueRef v) {
			return new Expr.Var(v.getValue().getName());
		}
		if (e instanceof BooleanLiteral l) {
			return new Expr.Lit(l.isValue());
		}
		if (e instanceof IntLiteral l) {
			return new Expr.Lit(l.getValue());
		}
		if (e instanceof DecimalLiteral l) {
			return new Expr.Lit(l.getValue());
		}
		if (e instanceof StringLiteral l) {
			return new Expr.Lit(l.getValue());
		}
		if (e instanceof MemberRef r && r.getOwner() instanceof Enumeration en) {
			return new Expr.EnumLit(en.getName(), ((EnumLiteral) r.getMember()).getName());
		}
		if (e instanceof MemberRef r && r.getMember() instanceof Attribute a && r.getOwner() instanceof org.triad.dsl.triad.Value v) {
			return new Expr.Call(((DomainClass) a.eContainer()).getName(), a.getName(), List.of(new Expr.Var(v.getName())));
		}
		throw new IllegalArgumentException("not an expression of the Triad languages: " + e);
	}
}
