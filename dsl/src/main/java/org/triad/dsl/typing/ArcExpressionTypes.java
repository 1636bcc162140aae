package org.triad.dsl.typing;

import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.EcoreUtil2;
import org.triad.dsl.arc.ArcNamedElement;
import org.triad.dsl.arc.ArcPort;
import org.triad.dsl.arc.BinaryExpression;
import org.triad.dsl.arc.BooleanLiteral;
import org.triad.dsl.arc.ComponentType;
import org.triad.dsl.arc.ConfigParameter;
import org.triad.dsl.arc.Direction;
import org.triad.dsl.arc.Expression;
import org.triad.dsl.arc.MemberAccess;
import org.triad.dsl.arc.NameRef;
import org.triad.dsl.arc.NewInstance;
import org.triad.dsl.arc.NullLiteral;
import org.triad.dsl.arc.NumberLiteral;
import org.triad.dsl.arc.StringLiteral;
import org.triad.dsl.arc.Transition;
import org.triad.dsl.arc.UnaryExpression;
import org.triad.dsl.arc.Variable;
import org.triad.dsl.semantics.ArcModels;
import org.triad.dsl.validation.ArcIssueCodes;

/**
 * Types of the expressions in guards, actions and variable initialisers of .arc automata. Types are
 * Java type names as written. Numbers, Booleans, strings and their boxes are known exactly (Java's
 * promotion and assignment rules); any other Java type is known by name only, so a member of it
 * ({@code x.foo()}) has the unknown type {@link #UNKNOWN}, which the Java compiler checks in the
 * generated code. Type parameters of a generic component match only themselves (and Object).
 */
public final class ArcExpressionTypes {
	/** The type of an expression the models cannot know (a member of a Java type). */
	public static final String UNKNOWN = "?";
	public static final String NULL = "null";

	/** Where type problems go; {@link #IGNORE} for callers that only want types. */
	public interface Problems {
		void report(String code, String message, EObject where);
	}

	public static final Problems IGNORE = (code, message, where) -> {
	};

	private enum Kind { NUMERIC, BOOLEAN, STRING, NULL, REFERENCE, UNKNOWN }

	private static final List<String> NUMERIC_RANK = List.of("byte", "short", "char", "int", "long", "float", "double");
	private static final Map<String, String> UNBOXED = Map.ofEntries(Map.entry("Byte", "byte"), Map.entry("Short", "short"),
			Map.entry("Character", "char"), Map.entry("Integer", "int"), Map.entry("Long", "long"), Map.entry("Float", "float"),
			Map.entry("Double", "double"), Map.entry("Boolean", "boolean"));
	/** Reference types every boxed number, Boolean and String can be assigned to. */
	private static final Set<String> SUPERTYPES_OF_VALUES = Set.of("Object", "Number", "Comparable", "Serializable", "CharSequence",
			"java.lang.Object", "java.lang.Number", "java.lang.Comparable", "java.io.Serializable", "java.lang.CharSequence");

	private ArcExpressionTypes() {
	}

	/** The expression's type without reporting problems. */
	public static String typeOf(Expression e) {
		return check(e, IGNORE);
	}

	/** The expression's type; problems found in it go to {@code problems}. */
	public static String check(Expression e, Problems problems) {
		if (e == null) {
			return UNKNOWN;
		}
		if (e instanceof NumberLiteral n) {
			return n.getText() != null && n.getText().contains(".") ? "double" : "int";
		}
		if (e instanceof BooleanLiteral) {
			return "boolean";
		}
		if (e instanceof StringLiteral) {
			return "String";
		}
		if (e instanceof NullLiteral) {
			return NULL;
		}
		if (e instanceof NewInstance n) {
			n.getArguments().forEach(a -> check(a, problems));
			return n.getType() == null ? UNKNOWN : n.getType().trim();
		}
		if (e instanceof NameRef r) {
			return nameType(r, problems);
		}
		if (e instanceof MemberAccess m) {
			String receiver = check(m.getReceiver(), problems);
			m.getArguments().forEach(a -> check(a, problems));
			if (isPrimitive(receiver)) {
				problems.report(ArcIssueCodes.EXPRESSION_TYPE, "a value of type " + receiver + " has no member '" + m.getMember() + "'", m);
			}
			return UNKNOWN;
		}
		if (e instanceof UnaryExpression u) {
			String operand = check(u.getOperand(), problems);
			if ("!".equals(u.getOp())) {
				expect(Kind.BOOLEAN, operand, "operand of '!'", u, problems);
				return "boolean";
			}
			expect(Kind.NUMERIC, operand, "operand of unary '-'", u, problems);
			return kind(operand) == Kind.NUMERIC ? promote(operand, "int") : UNKNOWN;
		}
		if (e instanceof BinaryExpression b) {
			return binary(b, problems);
		}
		if (e instanceof org.triad.dsl.arc.ConditionalExpression c) {
			String condition = check(c.getCondition(), problems);
			expect(Kind.BOOLEAN, condition, "condition of '?:'", c, problems);
			String then = check(c.getThen(), problems);
			String otherwise = check(c.getOtherwise(), problems);
			return then.equals(otherwise) ? then : UNKNOWN;
		}
		return UNKNOWN;
	}

	private static String binary(BinaryExpression b, Problems problems) {
		String l = check(b.getLeft(), problems);
		String r = check(b.getRight(), problems);
		String op = b.getOp();
		switch (op) {
		case "&&", "||" -> {
			expect(Kind.BOOLEAN, l, "left operand of '" + op + "'", b, problems);
			expect(Kind.BOOLEAN, r, "right operand of '" + op + "'", b, problems);
			return "boolean";
		}
		case "==", "!=" -> {
			if (!comparable(l, r, b)) {
				problems.report(ArcIssueCodes.EXPRESSION_TYPE, "cannot compare " + l + " with " + r + " by '" + op + "'", b);
			}
			return "boolean";
		}
		case "&", "|", "^" -> {
			if (kind(l) == Kind.BOOLEAN && kind(r) == Kind.BOOLEAN) {
				return "boolean";
			}
		}
		case "<<", ">>", ">>>" -> {
			expect(Kind.NUMERIC, l, "left operand of '" + op + "'", b, problems);
			expect(Kind.NUMERIC, r, "right operand of '" + op + "'", b, problems);
			return kind(l) == Kind.NUMERIC ? promote(l, "int") : UNKNOWN;
		}
				case "<", "<=", ">", ">=" -> {
			expect(Kind.NUMERIC, l, "left operand of '" + op + "'", b, problems);
			expect(Kind.NUMERIC, r, "right operand of '" + op + "'", b, problems);
			return "boolean";
		}
		case "+" -> {
			if (kind(l) == Kind.STRING || kind(r) == Kind.STRING) {
				return "String";
			}
			if (kind(l) == Kind.UNKNOWN || kind(r) == Kind.UNKNOWN) {
				return UNKNOWN;
			}
		}
		default -> {
			// - * / %
		}
		}
		expect(Kind.NUMERIC, l, "left operand of '" + op + "'", b, problems);
		expect(Kind.NUMERIC, r, "right operand of '" + op + "'", b, problems);
		return kind(l) == Kind.NUMERIC && kind(r) == Kind.NUMERIC ? promote(l, r) : UNKNOWN;
	}

	private static String nameType(NameRef r, Problems problems) {
		ArcNamedElement target = r.getTarget();
		if (target == null || target.eIsProxy()) {
			return UNKNOWN;
		}
		if (target instanceof Variable v) {
			return v.getType() == null ? UNKNOWN : v.getType().trim();
		}
		if (target instanceof org.triad.dsl.arc.LocalVariable v) {
			return v.getType() == null ? UNKNOWN : v.getType().trim();
		}
		if (target instanceof ConfigParameter p) {
			return p.getType() == null ? UNKNOWN : p.getType().trim();
		}
		if (target instanceof ArcPort port) {
			Transition t = EcoreUtil2.getContainerOfType(r, Transition.class);
			if (ArcModels.direction(port) == Direction.OUT) {
				problems.report(ArcIssueCodes.PORT_NOT_READABLE, "outgoing port '" + port.getName() + "' cannot be read: it only sends", r);
				return UNKNOWN;
			}
			String timedProblem = timedReadProblem(r);
			if (timedProblem != null) {
				if (!timedProblem.isEmpty()) {
					problems.report(ArcIssueCodes.PORT_NOT_READABLE, "incoming port '" + port.getName() + "' has no message here: " + timedProblem, r);
					return UNKNOWN;
				}
				return ArcModels.typeName(port).trim();
			}
			if (t == null || t.getTrigger() != port) {
				problems.report(ArcIssueCodes.PORT_NOT_READABLE, "incoming port '" + port.getName() + "' has no message here: "
						+ (t == null ? "a variable's initial value reads no port"
								: t.getTrigger() == null ? "the transition has no trigger (write 'on " + port.getName() + "')"
										: "only the trigger port '" + t.getTrigger().getName() + "' carries one"),
						r);
				return UNKNOWN;
			}
			return ArcModels.typeName(port).trim();
		}
		return UNKNOWN;
	}

	/**
	 * For a port read in a component that runs in time slices: "" when it is readable (each slice it
	 * holds the slice's message or null), the reason when it is not (initial actions and the init block
	 * run before the first slice, MontiArc's NoInputPortsInInitialOutputDecl), null for an event automaton
	 * of such a component or an event-driven component (the trigger rule applies).
	 */
	private static String timedReadProblem(EObject r) {
		ComponentType c = ArcModels.component(r);
		if (c == null || !ArcModels.isTimed(c)) {
			return null;
		}
		for (EObject e = r; e != null && e != c; e = e.eContainer()) {
			if (e.eContainingFeature() == org.triad.dsl.arc.ArcPackage.Literals.AUTOMATON_STATE__INITIAL_ACTIONS
					|| e.eContainingFeature() == org.triad.dsl.arc.ArcPackage.Literals.COMPONENT_TYPE__INIT_ACTIONS) {
				return "initial actions run before the first time slice";
			}
			if (e instanceof Variable) {
				return null;
			}
		}
		org.triad.dsl.arc.Automaton a = EcoreUtil2.getContainerOfType(r, org.triad.dsl.arc.Automaton.class);
		if (a != null && a.getStereotype() == null && ArcModels.allTransitions(a).stream().anyMatch(t -> t.getTrigger() != null)) {
			return null;
		}
		return "";
	}

	/** Whether a value of type {@code from} may be assigned (or sent) to something of type {@code to} in component {@code c}. */
	public static boolean isAssignable(String from, String to, ComponentType c) {
		Kind f = kind(from);
		Kind t = kind(to);
		if (f == Kind.UNKNOWN || t == Kind.UNKNOWN) {
			return true;
		}
		if (f == Kind.NULL) {
			return !isPrimitive(to);
		}
		boolean fromVariable = isTypeParameter(from, c);
		boolean toVariable = isTypeParameter(to, c);
		if (fromVariable || toVariable) {
			return ArcTypes.erasure(from).equals(ArcTypes.erasure(to)) || SUPERTYPES_OF_VALUES.contains(ArcTypes.erasure(to));
		}
		if (t == Kind.REFERENCE) {
			return f == Kind.REFERENCE || SUPERTYPES_OF_VALUES.contains(ArcTypes.erasure(to));
		}
		if (f != t) {
			return false;
		}
		if (f == Kind.NUMERIC) {
			String fp = unboxed(from);
			String tp = unboxed(to);
			if (!isPrimitive(to)) {
				return fp.equals(tp); // boxing only into the number's own box
			}
			return NUMERIC_RANK.indexOf(fp) <= NUMERIC_RANK.indexOf(tp) && !(fp.equals("char") != tp.equals("char") && NUMERIC_RANK.indexOf(tp) < 3);
		}
		return true;
	}

	/** Whether the generated Java compares with {@code ==} (a primitive side) rather than {@code Objects.equals}. */
	public static boolean comparesByValue(Expression left, Expression right) {
		return isPrimitive(typeOf(left)) || isPrimitive(typeOf(right));
	}

	public static boolean isBoolean(String type) {
		return kind(type) == Kind.BOOLEAN || kind(type) == Kind.UNKNOWN;
	}

	public static boolean isPrimitive(String type) {
		return NUMERIC_RANK.contains(type) || "boolean".equals(type);
	}

	private static boolean comparable(String l, String r, EObject context) {
		Kind a = kind(l);
		Kind b = kind(r);
		if (a == Kind.UNKNOWN || b == Kind.UNKNOWN) {
			return true;
		}
		if (a == Kind.NULL || b == Kind.NULL) {
			return !isPrimitive(a == Kind.NULL ? r : l);
		}
		if (a == Kind.REFERENCE || b == Kind.REFERENCE) {
			ComponentType c = ArcModels.component(context);
			return a == b || !(isTypeParameter(l, c) || isTypeParameter(r, c)) && SUPERTYPES_OF_VALUES.contains(ArcTypes.erasure(a == Kind.REFERENCE ? l : r));
		}
		return a == b;
	}

	private static void expect(Kind expected, String actual, String what, EObject where, Problems problems) {
		Kind k = kind(actual);
		if (k != expected && k != Kind.UNKNOWN) {
			problems.report(ArcIssueCodes.EXPRESSION_TYPE,
					what + " must be " + (expected == Kind.BOOLEAN ? "boolean" : "a number") + ", not " + actual, where);
		}
	}

	private static Kind kind(String type) {
		if (type == null || type.equals(UNKNOWN)) {
			return Kind.UNKNOWN;
		}
		if (type.equals(NULL)) {
			return Kind.NULL;
		}
		String p = unboxed(type);
		if (p.equals("boolean")) {
			return Kind.BOOLEAN;
		}
		if (NUMERIC_RANK.contains(p)) {
			return Kind.NUMERIC;
		}
		if (type.equals("String") || type.equals("java.lang.String")) {
			return Kind.STRING;
		}
		return Kind.REFERENCE;
	}

	private static String unboxed(String type) {
		String simple = type.startsWith("java.lang.") ? type.substring("java.lang.".length()) : type;
		return UNBOXED.getOrDefault(simple, simple);
	}

	/** Binary numeric promotion. */
	private static String promote(String a, String b) {
		int rank = Math.max(Math.max(NUMERIC_RANK.indexOf(unboxed(a)), NUMERIC_RANK.indexOf(unboxed(b))), NUMERIC_RANK.indexOf("int"));
		return NUMERIC_RANK.get(rank);
	}

	private static boolean isTypeParameter(String type, ComponentType c) {
		return c != null && ArcModels.typeParameterNames(c).contains(ArcTypes.erasure(type));
	}
}
