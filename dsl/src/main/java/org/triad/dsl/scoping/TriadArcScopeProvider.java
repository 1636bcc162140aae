package org.triad.dsl.scoping;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.scoping.IScope;
import org.eclipse.xtext.scoping.Scopes;
import org.triad.dsl.arc.ArcPackage;
import org.triad.dsl.arc.Automaton;
import org.triad.dsl.arc.ComponentType;
import org.triad.dsl.arc.PortRef;
import org.triad.dsl.arc.Subcomponent;
import org.triad.dsl.semantics.ArcModels;

/**
 * Ports, subcomponents and states are local names: {@code p} is a port of the enclosing component,
 * {@code sub.p} a port of the subcomponent's type, a transition names states of its automaton and a
 * port as trigger, and guards and actions name the component's variables, parameters and ports.
 * Component types go through the import-aware default (qualified names, imports, same package).
 */
public class TriadArcScopeProvider extends AbstractTriadArcScopeProvider {
	private static final ArcPackage A = ArcPackage.eINSTANCE;

	@Override
	public IScope getScope(EObject context, EReference reference) {
		if (reference == A.getPortRef_Port()) {
			if (context instanceof PortRef ref && ref.getSubcomponent() != null) {
				Subcomponent sub = ref.getSubcomponent();
				ComponentType type = sub.eIsProxy() ? null : sub.getType();
				return type == null || type.eIsProxy() ? IScope.NULLSCOPE : Scopes.scopeFor(ArcModels.ports(type));
			}
			ComponentType owner = EcoreUtil2.getContainerOfType(context, ComponentType.class);
			return owner == null ? IScope.NULLSCOPE : Scopes.scopeFor(ArcModels.ports(owner));
		}
		if (reference == A.getPortRef_Subcomponent()) {
			ComponentType owner = EcoreUtil2.getContainerOfType(context, ComponentType.class);
			return owner == null ? IScope.NULLSCOPE : Scopes.scopeFor(owner.getSubcomponents());
		}
		if (reference == A.getNameRef_Target() || reference == A.getAssignment_Target() || reference == A.getTransition_Trigger()) {
			ComponentType owner = EcoreUtil2.getContainerOfType(context, ComponentType.class);
			if (owner == null) {
				return IScope.NULLSCOPE;
			}
			return Scopes.scopeFor(reference == A.getTransition_Trigger() ? ArcModels.ports(owner) : ArcModels.members(owner));
		}
		if (reference == A.getTransition_Source() || reference == A.getTransition_Target()) {
			Automaton automaton = EcoreUtil2.getContainerOfType(context, Automaton.class);
			return automaton == null ? IScope.NULLSCOPE : Scopes.scopeFor(automaton.getStates());
		}
		return super.getScope(context, reference);
	}
}
