package org.triad.dsl.scoping;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.scoping.IScope;
import org.eclipse.xtext.scoping.Scopes;
import org.eclipse.xtext.scoping.impl.FilteringScope;
import org.triad.dsl.triad.Actor;
import org.triad.dsl.triad.AttributeAssignment;
import org.triad.dsl.triad.MemberRef;
import org.triad.dsl.triad.Value;
import org.triad.dsl.triad.Enumeration;
import org.triad.dsl.triad.ObjectDeclaration;
import org.triad.dsl.triad.Parameterized;
import org.triad.dsl.triad.PropertyCall;
import org.triad.dsl.triad.Situation;
import org.triad.dsl.triad.Goal;
import org.triad.dsl.triad.Parameter;
import org.triad.dsl.triad.UnsupportedConstruct;
import org.triad.dsl.triad.SituationObject;
import org.triad.dsl.semantics.SituationLineage;
import org.triad.dsl.triad.TriadPackage;
import org.triad.dsl.typing.TriadTypeSystem;

/**
 * Scoping shared by all Triad languages: names inside a model element (properties of an actor,
 * literals of an enumeration, parameters, a situation's objects, a class's attributes) are
 * resolved locally; everything else (types, actors, goals) globally, see
 * {@link DomainImportScopeProvider}.
 */
public class TriadCommonScopeProvider extends AbstractTriadCommonScopeProvider {
	private static final TriadPackage P = TriadPackage.eINSTANCE;

	@Override
	public IScope getScope(EObject context, EReference reference) {
		if (reference == P.getPropertyCall_Property() && context instanceof PropertyCall call) {
			return propertyScope(call);
		}
		if (reference == P.getMemberRef_Owner()) {
			// 'x.m': a parameter or object named x hides an enumeration of that name
			IScope enumerations = new FilteringScope(super.getScope(context, reference), d -> P.getEnumeration().isSuperTypeOf(d.getEClass()));
			return Scopes.scopeFor(valueScopeElements(context), enumerations);
		}
		if (reference == P.getMemberRef_Member() && context instanceof MemberRef ref) {
			return memberScope(ref);
		}
		if (reference == P.getValueRef_Value()) {
			return valueScope(context);
		}
		if (reference == P.getAttributeAssignment_Attribute()) {
			return attributeScope(context);
		}
		return super.getScope(context, reference);
	}

	private IScope propertyScope(PropertyCall call) {
		Actor actor = call.getActor();
		if (actor == null) {
			// unqualified calls mean the enclosing actor's own properties
			actor = EcoreUtil2.getContainerOfType(call, Actor.class);
		}
		return actor == null || actor.eIsProxy() ? IScope.NULLSCOPE : Scopes.scopeFor(actor.getProperties());
	}

	/** The literals of an enumeration, or the attributes of an object's class and its superclasses. */
	private static IScope memberScope(MemberRef ref) {
		EObject owner = ref.getOwner();
		if (owner == null || owner.eIsProxy()) {
			return IScope.NULLSCOPE;
		}
		if (owner instanceof Enumeration e) {
			return Scopes.scopeFor(e.getLiterals());
		}
		if (owner instanceof Value v && TriadTypeSystem.typeOf(v).domainClass() != null) {
			return Scopes.scopeFor(TriadTypeSystem.allAttributes(TriadTypeSystem.typeOf(v).domainClass()));
		}
		return IScope.NULLSCOPE;
	}

	private IScope valueScope(EObject context) {
		return Scopes.scopeFor(valueScopeElements(context));
	}

	private List<? extends EObject> valueScopeElements(EObject context) {
		Situation situation = EcoreUtil2.getContainerOfType(context, Situation.class);
		if (situation != null) {
			// a situation's own objects, then those it inherits (state B extends A), nearest first
			List<SituationObject> objects = new ArrayList<>();
			for (Situation s : SituationLineage.lineage(situation)) {
				for (ObjectDeclaration d : s.getDeclarations()) {
					objects.addAll(d.getObjects());
				}
			}
			return objects;
		}
		Parameterized owner = EcoreUtil2.getContainerOfType(context, Parameterized.class);
		// the variables of a 'forall (Room r)' the language does not have resolve, so that it is one finding, not many
		List<Parameter> variables = new ArrayList<>();
		for (EObject c = context; c != null && c != owner; c = c.eContainer()) {
			if (c instanceof UnsupportedConstruct u) {
				u.getParts().stream().filter(Parameter.class::isInstance).map(Parameter.class::cast).forEach(variables::add);
			}
		}
		if (owner instanceof Goal goal) {
			goal.getUnsupported().forEach(u -> u.getParts().stream().filter(Parameter.class::isInstance).map(Parameter.class::cast).forEach(variables::add));
		}
		if (owner == null) {
			return List.of();
		}
		List<Parameter> visible = new ArrayList<>(owner.getParameters());
		visible.addAll(variables);
		return visible;
	}

	private IScope attributeScope(EObject context) {
		ObjectDeclaration declaration = EcoreUtil2.getContainerOfType(context, ObjectDeclaration.class);
		if (declaration == null || declaration.getType() == null || declaration.getType().eIsProxy()) {
			return IScope.NULLSCOPE;
		}
		return Scopes.scopeFor(TriadTypeSystem.allAttributes(declaration.getType()));
	}
}
