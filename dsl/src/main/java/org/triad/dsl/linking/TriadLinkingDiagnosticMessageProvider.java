package org.triad.dsl.linking;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;

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
import org.triad.dsl.triad.Attribute;
import org.triad.dsl.triad.DomainClass;
import org.triad.dsl.triad.EnumLiteral;
import org.triad.dsl.triad.Enumeration;
import org.triad.dsl.triad.MemberRef;
import org.triad.dsl.triad.Value;
import org.triad.dsl.typing.TriadType;
import org.triad.dsl.typing.TriadTypeSystem;
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
		if (ref == P.getMemberRef_Owner()) {
			return error(CommonIssueCodes.UNKNOWN_ENUMERATION, "unknown name '" + name + "' before '.': no parameter, object or enumeration '"
					+ name + "' here");
		}
		if (ref == P.getMemberRef_Member() && context.getContext() instanceof MemberRef read) {
			return memberMessage(read, name);
		}
		if (target == P.getAttribute()) {
			return error(CommonIssueCodes.UNKNOWN_ATTRIBUTE, "unknown attribute '" + name + "'");
		}
		return error(CommonIssueCodes.UNKNOWN_NAME, "unknown " + target.getName() + " '" + name + "'");
	}

	/** 'X.m' where m is not a member of X: no such literal, no such attribute, or an attribute of another class. */
	private static DiagnosticMessage memberMessage(MemberRef read, String name) {
		EObject owner = read.getOwner();
		if (owner == null) {
			return error(CommonIssueCodes.UNKNOWN_LITERAL, "unknown enumeration literal or attribute '" + name + "'");
		}
		if (owner.eIsProxy()) {
			return null; // the unknown name before the dot is reported; its members cannot be known
		}
		if (owner instanceof Enumeration e) {
			return error(CommonIssueCodes.UNKNOWN_LITERAL, "unknown enumeration literal '" + name + "' of " + e.getName() + " (its literals: "
					+ e.getLiterals().stream().map(EnumLiteral::getName).collect(Collectors.joining(", ")) + ")");
		}
		Value value = (Value) owner;
		TriadType type = TriadTypeSystem.typeOf(value);
		DomainClass c = type.domainClass();
		if (c == null) {
			return error(CommonIssueCodes.UNKNOWN_ATTRIBUTE, "'" + value.getName() + "." + name + "': '" + value.getName() + "' is "
					+ (type.isUnknown() ? "of an unknown type" : (type.display().matches("[aeiouAEIOU].*") ? "an " : "a ") + type.display()) + ", not an object: only objects of classes have attributes");
		}
		List<DomainClass> declaring = classesDeclaring(read, name);
		if (!declaring.isEmpty()) {
			return error(CommonIssueCodes.ATTRIBUTE_OF_OTHER_CLASS, "'" + value.getName() + "." + name + "': '" + value.getName() + "' is a "
					+ c.getName() + ", and '" + name + "' is an attribute of " + declaring.stream().map(DomainClass::getName).collect(Collectors.joining(", "))
					+ ", not of " + c.getName() + (declaring.size() == 1 ? "; give '" + value.getName() + "' the type " + declaring.get(0).getName() + "?" : ""));
		}
		List<Attribute> attributes = TriadTypeSystem.allAttributes(c);
		return error(CommonIssueCodes.UNKNOWN_ATTRIBUTE, "unknown attribute '" + name + "' of " + c.getName() + " ('" + value.getName() + "." + name + "'; "
				+ (attributes.isEmpty() ? c.getName() + " has no attributes)"
						: "its attributes: " + attributes.stream().map(Attribute::getName).collect(Collectors.joining(", ")) + ")"));
	}

	/** The classes of the class diagram in use that declare an attribute {@code name}. */
	private static List<DomainClass> classesDeclaring(EObject context, String name) {
		DomainModel model = EcoreUtil2.getContainerOfType(context, DomainModel.class);
		if (model == null || model.getDomain() == null || model.getDomain().eIsProxy()) {
			return List.of();
		}
		List<DomainClass> result = new ArrayList<>();
		for (org.triad.dsl.triad.DomainType t : model.getDomain().getTypes()) {
			if (t instanceof DomainClass dc && dc.getAttributes().stream().anyMatch(a -> name.equals(a.getName()))) {
				result.add(dc);
			}
		}
		return result;
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
