package org.triad.dsl.scoping;

import org.eclipse.emf.ecore.EObject;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.scoping.IScope;
import org.eclipse.xtext.scoping.Scopes;
import org.triad.dsl.arc.ArcPackage;
import org.triad.dsl.arc.Automaton;
import org.triad.dsl.arc.ComponentType;
import org.triad.dsl.arc.LocalVariable;
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
				ComponentType type = sub.eIsProxy() ? null : ArcModels.type(sub);
				return type == null || type.eIsProxy() ? IScope.NULLSCOPE : Scopes.scopeFor(ArcModels.ports(type));
			}
			ComponentType owner = EcoreUtil2.getContainerOfType(context, ComponentType.class);
			return owner == null ? IScope.NULLSCOPE : Scopes.scopeFor(ArcModels.ports(owner));
		}
		if (reference == A.getPortRef_Subcomponent()) {
			ComponentType owner = EcoreUtil2.getContainerOfType(context, ComponentType.class);
			return owner == null ? IScope.NULLSCOPE : Scopes.scopeFor(ArcModels.subcomponents(owner));
		}
		if (reference == A.getNameRef_Target() || reference == A.getAssignment_Target() || reference == A.getTransition_Trigger()) {
			ComponentType owner = EcoreUtil2.getContainerOfType(context, ComponentType.class);
			if (owner == null) {
				return IScope.NULLSCOPE;
			}
			if (reference == A.getTransition_Trigger()) {
				return Scopes.scopeFor(ArcModels.ports(owner));
			}
			return Scopes.scopeFor(localsBefore(context), Scopes.scopeFor(ArcModels.members(owner)));
		}
		if (reference == A.getTransition_Source() || reference == A.getTransition_Target()) {
			Automaton automaton = EcoreUtil2.getContainerOfType(context, Automaton.class);
			return automaton == null ? IScope.NULLSCOPE : Scopes.scopeFor(ArcModels.allStates(automaton));
		}
		return super.getScope(context, reference);
	}

	/** Local variables declared before the context in its enclosing statement lists, innermost first (Java's block scoping). */
	private static List<LocalVariable> localsBefore(EObject context) {
		List<LocalVariable> locals = new ArrayList<>();
		EObject child = context;
		for (EObject parent = context.eContainer(); parent != null && !(parent instanceof ComponentType); child = parent, parent = parent.eContainer()) {
			EStructuralFeature feature = child.eContainingFeature();
			if (feature != null && feature.isMany()) {
				List<LocalVariable> here = new ArrayList<>();
				for (Object o : (List<?>) parent.eGet(feature)) {
					if (o == child) {
						break;
					}
					if (o instanceof LocalVariable v) {
						here.add(0, v);
					}
				}
				locals.addAll(here);
			}
		}
		if (child.eContainingFeature() != null && child.eContainingFeature().isMany() && child.eContainer() instanceof ComponentType c) {
			for (Object o : (List<?>) c.eGet(child.eContainingFeature())) {
				if (o == child) {
					break;
				}
				if (o instanceof LocalVariable v) {
					locals.add(v);
				}
			}
		}
		return locals;
	}
}
