package org.triad.dsl.ide;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.lsp4j.MarkupContent;
import org.eclipse.lsp4j.MarkupKind;
import org.eclipse.lsp4j.ParameterInformation;
import org.eclipse.lsp4j.SignatureHelp;
import org.eclipse.lsp4j.SignatureHelpParams;
import org.eclipse.lsp4j.SignatureInformation;
import org.eclipse.lsp4j.jsonrpc.messages.Tuple;
import org.eclipse.xtext.ide.server.Document;
import org.eclipse.xtext.ide.server.signatureHelp.ISignatureHelpService;
import org.eclipse.xtext.naming.QualifiedName;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.scoping.IScopeProvider;
import org.eclipse.xtext.util.CancelIndicator;
import org.triad.dsl.ide.hover.ModelDocumentation;
import org.triad.dsl.ide.hover.ModelSignatures;
import org.triad.dsl.triad.Actor;
import org.triad.dsl.triad.ActorModel;
import org.triad.dsl.triad.Goal;
import org.triad.dsl.triad.Parameter;
import org.triad.dsl.triad.Parameterized;
import org.triad.dsl.triad.Property;
import org.triad.dsl.triad.TaskModel;
import org.triad.dsl.triad.TriadPackage;

import com.google.inject.Inject;

/**
 * Signature help inside a call: a goal's parameters in a task's step ({@code Holds(|)}), a
 * property's parameters in an expression ({@code Building.adj(a, |)}), with the parameter under
 * the cursor marked. Works on the text, because while a call is being typed it is not yet a model
 * element; names are resolved through scoping like the finished call would be.
 */
public class ModelSignatureHelp implements ISignatureHelpService {
	private static final TriadPackage P = TriadPackage.eINSTANCE;

	@Inject
	private IScopeProvider scopes;

	@Inject
	private ModelDocumentation documentation;

	/** The call around the cursor, read from the text. */
	record OpenCall(String qualifier, String name, int activeParameter) {
	}

	@Override
	public SignatureHelp getSignatureHelp(Document document, XtextResource resource, SignatureHelpParams params, CancelIndicator cancel) {
		if (resource.getContents().isEmpty()) {
			return EMPTY;
		}
		OpenCall call = openCall(document.getContents(), document.getOffSet(params.getPosition()));
		if (call == null) {
			return EMPTY;
		}
		EObject root = resource.getContents().get(0);
		Parameterized target = resolve(root, call);
		if (target == null) {
			return EMPTY;
		}
		return help(target, call);
	}

	private SignatureHelp help(Parameterized target, OpenCall call) {
		String prefix = target instanceof Property p ? "property " + ModelSignatures.type(p.getType()) + " "
				+ (call.qualifier() == null ? "" : call.qualifier() + ".") : ModelSignatures.kind(target) + " ";
		StringBuilder label = new StringBuilder(prefix).append(target.getName()).append('(');
		List<ParameterInformation> parameters = new ArrayList<>();
		for (Parameter p : target.getParameters()) {
			if (!parameters.isEmpty()) {
				label.append(", ");
			}
			int start = label.length();
			label.append(ModelSignatures.parameter(p));
			parameters.add(new ParameterInformation());
			parameters.get(parameters.size() - 1).setLabel(Tuple.two(start, label.length()));
		}
		label.append(')');
		SignatureInformation signature = new SignatureInformation(label.toString());
		signature.setParameters(parameters);
		String doc = documentation.getDocumentation(target);
		if (doc != null) {
			signature.setDocumentation(new MarkupContent(MarkupKind.MARKDOWN, doc));
		}
		int active = Math.min(call.activeParameter(), Math.max(0, parameters.size() - 1));
		signature.setActiveParameter(active);
		return new SignatureHelp(List.of(signature), 0, active);
	}

	private Parameterized resolve(EObject root, OpenCall call) {
		if (call.qualifier() != null) {
			Actor actor = lookup(root, P.getPropertyCall_Actor(), call.qualifier(), Actor.class);
			return actor == null ? null : property(actor, call.name());
		}
		if (root instanceof ActorModel m && m.getActor() != null) {
			return property(m.getActor(), call.name());
		}
		if (root instanceof TaskModel) {
			return lookup(root, P.getGoalReference_Goal(), call.name(), Goal.class);
		}
		return null;
	}

	private static Property property(Actor actor, String name) {
		return actor.getProperties().stream().filter(p -> name.equals(p.getName())).findFirst().orElse(null);
	}

	private <T> T lookup(EObject context, EReference ref, String name, Class<T> type) {
		IEObjectDescription d = scopes.getScope(context, ref).getSingleElement(QualifiedName.create(name));
		if (d == null) {
			return null;
		}
		EObject o = d.getEObjectOrProxy();
		if (o.eIsProxy()) {
			o = EcoreUtil.resolve(o, context);
		}
		return type.isInstance(o) && !o.eIsProxy() ? type.cast(o) : null;
	}

	private static final List<String> DECLARING = List.of("goal", "task", "action", "property", "component");

	/**
	 * The innermost call whose '(' is open at {@code offset} within the current statement, or null;
	 * declarations ({@code goal Holds(}) are not calls.
	 */
	static OpenCall openCall(String text, int offset) {
		int depth = 0;
		int commas = 0;
		int i = Math.min(offset, text.length()) - 1;
		for (; i >= 0; i--) {
			char c = text.charAt(i);
			if (c == '"') {
				return null; // inside or after a string: too ambiguous to guess
			}
			if (c == ')') {
				depth++;
			} else if (c == '(') {
				if (depth == 0) {
					break;
				}
				depth--;
			} else if (c == ',' && depth == 0) {
				commas++;
			} else if (c == ';' || c == '{' || c == '}') {
				return null;
			}
		}
		if (i < 0) {
			return null;
		}
		int end = i;
		while (end > 0 && Character.isWhitespace(text.charAt(end - 1))) {
			end--;
		}
		int start = end;
		while (start > 0 && Character.isJavaIdentifierPart(text.charAt(start - 1))) {
			start--;
		}
		if (start == end) {
			return null;
		}
		String name = text.substring(start, end);
		String qualifier = null;
		if (start > 0 && text.charAt(start - 1) == '.') {
			int qEnd = start - 1;
			int qStart = qEnd;
			while (qStart > 0 && Character.isJavaIdentifierPart(text.charAt(qStart - 1))) {
				qStart--;
			}
			qualifier = qStart == qEnd ? null : text.substring(qStart, qEnd);
		}
		String lineBefore = text.substring(text.lastIndexOf('\n', start - 1) + 1, start).strip();
		String firstWord = lineBefore.split("\\s+")[0];
		if (DECLARING.contains(firstWord)) {
			return null;
		}
		return new OpenCall(qualifier, name, commas);
	}
}
