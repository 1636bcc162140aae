package org.triad.dsl.linking;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.diagnostics.DiagnosticMessage;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.linking.impl.LinkingDiagnosticMessageProvider;
import org.triad.dsl.triad.Actor;
import org.triad.dsl.triad.DomainModel;
import org.triad.dsl.triad.EnumLiteralRef;
import org.triad.dsl.triad.PropertyCall;
import org.triad.dsl.triad.TriadPackage;
import org.triad.dsl.validation.CommonIssueCodes;

/**
 * Unresolved names get a stable code per kind of element (unknown type, actor, property, goal,
 * parameter, ...) and a message a model author can act on.
 */
public class TriadLinkingDiagnosticMessageProvider extends LinkingDiagnosticMessageProvider {
	private static final TriadPackage P = TriadPackage.eINSTANCE;

	@Override
	public DiagnosticMessage getUnresolvedProxyMessage(ILinkingDiagnosticContext context) {
		EReference ref = context.getReference();
		String name = context.getLinkText();
		EClass target = ref.getEReferenceType();
		if (ref == P.getPropertyCall_Property() && context.getContext() instanceof PropertyCall call && call.getActor() == null
				&& EcoreUtil2.getContainerOfType(call, Actor.class) == null) {
			return error(CommonIssueCodes.UNQUALIFIED_CALL, "property call '" + name
					+ "' must name its actor here, e.g. 'Robot." + name + "(...)': only actions of an actor may omit it");
		}
		if (ref == P.getPropertyCall_Property() && context.getContext() instanceof PropertyCall call && call.getActor() != null
				&& call.getActor().eIsProxy()) {
			return null; // the unknown actor is reported; its properties cannot be known
		}
		if (ref == P.getPropertyCall_Property()) {
			String owner = context.getContext() instanceof PropertyCall call && call.getActor() != null && !call.getActor().eIsProxy()
					? "actor '" + call.getActor().getName() + "'" : "this actor";
			return error(CommonIssueCodes.UNKNOWN_PROPERTY, "unknown property '" + name + "' of " + owner);
		}
		if (ref == P.getValueRef_Value()) {
			return error(CommonIssueCodes.UNKNOWN_VALUE, "unknown parameter or object '" + name + "'");
		}
		if (ref == P.getDomainModel_Domain()) {
			return error(CommonIssueCodes.UNKNOWN_DOMAIN, "unknown class diagram '" + name + "' (no 'classdiagram " + name + "' in this application)");
		}
		if (target == P.getDomainType() || target == P.getDomainClass()) {
			if (isUnqualified(name) && hasUnknownDomain(context.getContext())) {
				return null; // the unknown 'domain D;' is reported; the types it would import cannot be known
			}
			return error(CommonIssueCodes.UNKNOWN_TYPE, "unknown type '" + name + "'");
		}
		if (target == P.getActor()) {
			return error(CommonIssueCodes.UNKNOWN_ACTOR, "unknown actor '" + name + "'");
		}
		if (target == P.getGoal()) {
			return error(CommonIssueCodes.UNKNOWN_GOAL, "unknown goal '" + name + "'");
		}
		if (target == P.getSituation()) {
			return error(CommonIssueCodes.UNKNOWN_SITUATION, "unknown situation '" + name + "' (no 'state " + name + "' in this application)");
		}
		if (target == P.getEnumeration() && context.getContext() instanceof EnumLiteralRef read) {
			String type = objectType(read, name);
			if (type != null) {
				String attribute = NodeModelUtils.getTokenText(NodeModelUtils.findActualNodeFor(read)).replaceAll("\\s+", "");
				attribute = attribute.substring(attribute.indexOf('.') + 1);
				return error(CommonIssueCodes.ATTRIBUTE_READ, "'" + name + "." + attribute + "' reads attribute '" + attribute + "' of object '" + name
						+ "': conditions read properties of actors, not attributes of objects; declare a world property, e.g. 'property int "
						+ attribute + "(" + type + " o);', state its values in situations and write 'World." + attribute + "(" + name + ")'");
			}
		}
		if (target == P.getEnumeration()) {
			return error(CommonIssueCodes.UNKNOWN_ENUMERATION, "unknown enumeration '" + name + "'");
		}
		if (target == P.getEnumLiteral()) {
			if (context.getContext() instanceof EnumLiteralRef literalRef && literalRef.getEnumeration() != null
					&& literalRef.getEnumeration().eIsProxy()) {
				return null; // the unknown enumeration is reported; its literals cannot be known
			}
			return error(CommonIssueCodes.UNKNOWN_LITERAL, "unknown enumeration literal '" + name + "'");
		}
		if (target == P.getAttribute()) {
			return error(CommonIssueCodes.UNKNOWN_ATTRIBUTE, "unknown attribute '" + name + "'");
		}
		return error(CommonIssueCodes.UNKNOWN_NAME, "unknown " + target.getName() + " '" + name + "'");
	}

	/** The type of the parameter or situation object {@code name} where {@code e} is written, or null if there is none. */
	private static String objectType(EObject e, String name) {
		for (EObject c = e; c != null; c = c.eContainer()) {
			if (c instanceof org.triad.dsl.triad.Parameterized owner) {
				for (org.triad.dsl.triad.Parameter p : owner.getParameters()) {
					if (name.equals(p.getName())) {
						return org.triad.dsl.typing.TriadTypeSystem.typeOf(p.getType()).display();
					}
				}
			}
			if (c instanceof org.triad.dsl.triad.Situation s) {
				for (org.triad.dsl.triad.ObjectDeclaration d : s.getDeclarations()) {
					for (org.triad.dsl.triad.SituationObject o : d.getObjects()) {
						if (name.equals(o.getName()) && d.getType() != null && !d.getType().eIsProxy()) {
							return d.getType().getName();
						}
					}
				}
			}
		}
		return null;
	}

	private static boolean isUnqualified(String name) {
		return name != null && !name.contains(".");
	}

	private static boolean hasUnknownDomain(EObject context) {
		DomainModel model = EcoreUtil2.getContainerOfType(context, DomainModel.class);
		return model != null && model.getDomain() != null && model.getDomain().eIsProxy();
	}

	private static DiagnosticMessage error(String code, String message) {
		return new DiagnosticMessage(message, Severity.ERROR, code);
	}
}
