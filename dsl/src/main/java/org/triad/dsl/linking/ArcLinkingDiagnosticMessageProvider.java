package org.triad.dsl.linking;

import org.triad.dsl.semantics.ArcModels;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.diagnostics.DiagnosticMessage;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.linking.impl.LinkingDiagnosticMessageProvider;
import org.triad.dsl.arc.ArcPackage;
import org.triad.dsl.arc.ComponentType;
import org.triad.dsl.arc.PortRef;
import org.triad.dsl.arc.Subcomponent;
import org.triad.dsl.validation.ArcIssueCodes;

/** Unresolved names in .arc models get a stable code per kind (component, port, subcomponent, state, name in a guard or action). */
public class ArcLinkingDiagnosticMessageProvider extends LinkingDiagnosticMessageProvider {
	private static final ArcPackage A = ArcPackage.eINSTANCE;

	@Override
	public DiagnosticMessage getUnresolvedProxyMessage(ILinkingDiagnosticContext context) {
		EReference ref = context.getReference();
		String name = context.getLinkText();
		if (ref == A.getSubcomponentDeclaration_Type() && context.getContext() instanceof org.triad.dsl.arc.SubcomponentDeclaration d
				&& org.eclipse.xtext.nodemodel.util.NodeModelUtils.getNode(d) != null
				&& (d.getInstances().isEmpty() || d.getInstances().stream().anyMatch(i -> i.getName() == null))) {
			return null; // a statement the parser could not read (reported as syntax) taken for a declaration in recovery
		}
		if (ref == A.getSubcomponentDeclaration_Type() || ref == A.getComponentType_Parent()) {
			return error(ArcIssueCodes.UNKNOWN_COMPONENT, "unknown component type '" + name
					+ "' (not in this package, not imported, no component of that qualified name)");
		}
		if (ref == A.getPortRef_Port() && context.getContext() instanceof PortRef portRef) {
			Subcomponent sub = portRef.getSubcomponent();
			if (sub != null) {
				if (sub.eIsProxy() || ArcModels.type(sub) == null || ArcModels.type(sub).eIsProxy()) {
					return null; // the unknown subcomponent or type is reported; its ports cannot be known
				}
				return error(ArcIssueCodes.UNKNOWN_PORT, "unknown port '" + name + "' of subcomponent '" + sub.getName()
						+ "' (component '" + ArcModels.type(sub).getName() + "')");
			}
			ComponentType owner = EcoreUtil2.getContainerOfType(portRef, ComponentType.class);
			return error(ArcIssueCodes.UNKNOWN_PORT, "unknown port '" + name + "' of component '"
					+ (owner == null ? "?" : owner.getName()) + "'");
		}
		if (ref == A.getPortRef_Subcomponent()) {
			ComponentType owner = EcoreUtil2.getContainerOfType(context.getContext(), ComponentType.class);
			return error(ArcIssueCodes.UNKNOWN_SUBCOMPONENT, "unknown subcomponent '" + name + "' of component '"
					+ (owner == null ? "?" : owner.getName()) + "'");
		}
		if (ref == A.getTransition_Trigger()) {
			ComponentType owner = EcoreUtil2.getContainerOfType(context.getContext(), ComponentType.class);
			return error(ArcIssueCodes.UNKNOWN_PORT, "unknown port '" + name + "' of component '"
					+ (owner == null ? "?" : owner.getName()) + "' as trigger");
		}
		if (ref == A.getNameRef_Target() && ArcModels.isQualifierPosition(context.getContext())) {
			return null; // Type.MEMBER: a Java or class-diagram type, checked by the validator (arc.unknown-name)
		}
		if (ref == A.getNameRef_Target() || ref == A.getAssignment_Target()) {
			ComponentType owner = EcoreUtil2.getContainerOfType(context.getContext(), ComponentType.class);
			return error(ArcIssueCodes.UNKNOWN_NAME, "unknown name '" + name + "': not a variable, configuration parameter or port of component '"
					+ (owner == null ? "?" : owner.getName()) + "'");
		}
		if (ref == A.getTransition_Source() || ref == A.getTransition_Target()) {
			return error(ArcIssueCodes.UNKNOWN_STATE, "unknown state '" + name + "' (not declared in this automaton)");
		}
		return super.getUnresolvedProxyMessage(context);
	}

	private static DiagnosticMessage error(String code, String message) {
		return new DiagnosticMessage(message, Severity.ERROR, code);
	}
}
