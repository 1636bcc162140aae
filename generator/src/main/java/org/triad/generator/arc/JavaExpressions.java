package org.triad.generator.arc;

import java.util.List;
import java.util.stream.Collectors;

import org.triad.dsl.arc.ArcNamedElement;
import org.triad.dsl.arc.ArcPort;
import org.triad.dsl.arc.Block;
import org.triad.dsl.arc.BreakStatement;
import org.triad.dsl.arc.IfStatement;
import org.triad.dsl.arc.LocalVariable;
import org.triad.dsl.arc.SwitchCase;
import org.triad.dsl.arc.SwitchStatement;
import org.triad.dsl.semantics.ArcModels;
import org.triad.dsl.arc.Assignment;
import org.triad.dsl.arc.BinaryExpression;
import org.triad.dsl.arc.BooleanLiteral;
import org.triad.dsl.arc.Expression;
import org.triad.dsl.arc.ExpressionStatement;
import org.triad.dsl.arc.MemberAccess;
import org.triad.dsl.arc.NameRef;
import org.triad.dsl.arc.NewInstance;
import org.triad.dsl.arc.NullLiteral;
import org.triad.dsl.arc.NumberLiteral;
import org.triad.dsl.arc.Statement;
import org.triad.dsl.arc.StringLiteral;
import org.triad.dsl.arc.UnaryExpression;
import org.triad.dsl.typing.ArcExpressionTypes;

/**
 * Guards and actions of validated automata as Java: an assignment to an outgoing port sends, {@code ==}
 * on objects is {@code Objects.equals}, and every compound expression is parenthesised so Java reads
 * it as the model's grammar did.
 */
public class JavaExpressions {
	private final ArcNames names;
	private final boolean timed;

	public JavaExpressions(ArcNames names) {
		this(names, false);
	}

	/** For a timed component, sending is {@code emit}: a delayed port holds the message for the next slice. */
	public JavaExpressions(ArcNames names, boolean timed) {
		this.names = names;
		this.timed = timed;
	}

	public String statement(Statement s) {
		if (s instanceof Assignment a) {
			ArcNamedElement target = a.getTarget();
			if (target instanceof ArcPort p) {
				return timed ? "emit(" + names.portField(p) + ", " + expression(a.getValue()) + ");"
						: names.portField(p) + ".send(" + expression(a.getValue()) + ");";
			}
			if (target instanceof LocalVariable) {
				return names.field(target) + " = " + expression(a.getValue()) + ";";
			}
			return "this." + names.field(target) + " = " + expression(a.getValue()) + ";";
		}
		if (s instanceof LocalVariable v) {
			return names.javaType(v.getType().trim()) + " " + names.field(v) + " = " + expression(v.getInitial()) + ";";
		}
		if (s instanceof Block b) {
			return "{\n" + statements(b.getStatements()) + "}";
		}
		if (s instanceof IfStatement i) {
			return "if (" + expression(i.getCondition()) + ") " + block(i.getThenBranch())
					+ (i.getElseBranch() == null ? "" : " else " + block(i.getElseBranch()));
		}
		if (s instanceof SwitchStatement sw) {
			StringBuilder b = new StringBuilder("switch (" + expression(sw.getSubject()) + ") {\n");
			for (SwitchCase c : sw.getCases()) {
				b.append(c.isOtherwise() ? "default:" : "case " + caseLabel(c.getLabel()) + ":").append(" {\n").append(statements(c.getStatements())).append("}\n");
			}
			return b.append("}").toString();
		}
		if (s instanceof BreakStatement) {
			return "break;";
		}
		return expression(((ExpressionStatement) s).getExpression()) + ";";
	}

	/** Statements, one a line. */
	public String statements(List<Statement> list) {
		StringBuilder b = new StringBuilder();
		for (Statement st : list) {
			b.append(statement(st)).append("\n");
		}
		return b.toString();
	}

	private String block(Statement s) {
		return s instanceof Block ? statement(s) : "{\n" + statement(s) + "\n}";
	}

	/** A case label: an enum constant is written without its type in Java. */
	private String caseLabel(Expression e) {
		if (e instanceof MemberAccess m && !m.isCall() && m.getReceiver() instanceof NameRef r && ArcModels.isTypeQualifier(r)) {
			return m.getMember();
		}
		return expression(e);
	}

	public String expression(Expression e) {
		if (e instanceof NumberLiteral n) {
			return n.getText();
		}
		if (e instanceof BooleanLiteral b) {
			return b.getText();
		}
		if (e instanceof StringLiteral s) {
			return stringLiteral(s.getValue());
		}
		if (e instanceof NullLiteral) {
			return "null";
		}
		if (e instanceof NameRef r) {
			if (ArcModels.isTypeQualifier(r)) {
				return names.javaType(ArcModels.qualifierText(r));
			}
			// the trigger port's message is the handler's parameter of the port's name; others are fields
			if (r.getTarget() instanceof ArcPort p) {
				return names.handlerParameter(p);
			}
			return r.getTarget() instanceof LocalVariable ? names.field(r.getTarget()) : "this." + names.field(r.getTarget());
		}
		if (e instanceof NewInstance n) {
			return "new " + n.getType().trim() + (n.isDiamond() ? "<>" : "") + "(" + arguments(n.getArguments()) + ")";
		}
		if (e instanceof MemberAccess m) {
			return expression(m.getReceiver()) + "." + m.getMember() + (m.isCall() ? "(" + arguments(m.getArguments()) + ")" : "");
		}
		if (e instanceof UnaryExpression u) {
			return u.getOp() + "(" + expression(u.getOperand()) + ")";
		}
		if (e instanceof org.triad.dsl.arc.ConditionalExpression c) {
			return "(" + expression(c.getCondition()) + " ? " + expression(c.getThen()) + " : " + expression(c.getOtherwise()) + ")";
		}
		BinaryExpression b = (BinaryExpression) e;
		String l = expression(b.getLeft());
		String r = expression(b.getRight());
		if ((b.getOp().equals("==") || b.getOp().equals("!=")) && !ArcExpressionTypes.comparesByValue(b.getLeft(), b.getRight())) {
			return (b.getOp().equals("!=") ? "!" : "") + "java.util.Objects.equals(" + l + ", " + r + ")";
		}
		return "(" + l + " " + b.getOp() + " " + r + ")";
	}

	private String arguments(List<Expression> args) {
		return args.stream().map(this::expression).collect(Collectors.joining(", "));
	}

	private static String stringLiteral(String value) {
		StringBuilder b = new StringBuilder("\"");
		for (char c : value.toCharArray()) {
			switch (c) {
			case '"' -> b.append("\\\"");
			case '\\' -> b.append("\\\\");
			case '\n' -> b.append("\\n");
			case '\r' -> b.append("\\r");
			case '\t' -> b.append("\\t");
			default -> b.append(c);
			}
		}
		return b.append('"').toString();
	}
}
