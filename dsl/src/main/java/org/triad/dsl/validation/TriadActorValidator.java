package org.triad.dsl.validation;

import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.resource.IResourceDescriptions;
import org.eclipse.xtext.resource.impl.ResourceDescriptionsProvider;
import org.eclipse.xtext.validation.Check;
import org.eclipse.xtext.validation.CheckType;
import org.triad.dsl.semantics.PostconditionEffect;
import org.triad.dsl.semantics.Postconditions;
import org.triad.dsl.triad.Action;
import org.triad.dsl.triad.Actor;
import org.triad.dsl.triad.NamedElement;
import org.triad.dsl.triad.Property;
import org.triad.dsl.triad.PropertyCall;
import org.triad.dsl.typing.TriadType;
import org.triad.dsl.typing.TriadTypeSystem;

import com.google.inject.Inject;

/** Rules of robot and world actors; codes in {@link ActorIssueCodes}. */
public class TriadActorValidator extends AbstractTriadActorValidator {
	@Inject
	private ResourceDescriptionsProvider indexProvider;

	@Check
	public void checkUniqueMembers(Actor actor) {
		Set<String> seen = new HashSet<>();
		for (NamedElement member : concat(actor)) {
			if (member.getName() != null && !seen.add(member.getName())) {
				error("duplicate member '" + member.getName() + "' of actor '" + actor.getName() + "'", member,
						P.getNamedElement_Name(), ActorIssueCodes.DUPLICATE_MEMBER);
			}
		}
	}

	private static Iterable<NamedElement> concat(Actor actor) {
		java.util.List<NamedElement> all = new java.util.ArrayList<>(actor.getProperties());
		all.addAll(actor.getActions());
		return all;
	}

	@Check
	public void checkPrecondition(Action action) {
		requireCondition(action.getPre(), "precondition of '" + action.getName() + "'", action, P.getAction_Pre());
	}

	@Check
	public void checkPostcondition(Action action) {
		Postconditions.Analysis analysis = Postconditions.analyse(action.getPost());
		for (Postconditions.Problem problem : analysis.problems()) {
			EObject at = problem.expression();
			error(problem.message(), at.eContainer(), at.eContainmentFeature(), indexIn(at),
					analysisCode(problem), new String[0]);
		}
		Map<String, PostconditionEffect> byTarget = new HashMap<>();
		for (PostconditionEffect effect : analysis.effects()) {
			if (effect.isAssignment()) {
				TriadType target = TriadTypeSystem.typeOf(effect.call());
				TriadType value = TriadTypeSystem.typeOf(effect.value());
				if (!TriadTypeSystem.isAssignable(target, value)) {
					error("'" + effect.call().getProperty().getName() + "' is " + target.display() + " and cannot be assigned "
							+ value.display(), effect.value().eContainer(), effect.value().eContainmentFeature(),
							ActorIssueCodes.EFFECT_VALUE);
				}
			}
			String key = targetKey(effect.call(), action);
			PostconditionEffect previous = byTarget.put(key, effect);
			if (previous != null) {
				error("the postcondition of '" + action.getName() + "' sets '" + key + "' twice", effect.call().eContainer(),
						effect.call().eContainmentFeature(), ActorIssueCodes.CONFLICTING_EFFECTS);
			}
		}
	}

	/**
	 * What an effect changes: the property (whether named as {@code p()} or {@code Actor.p()}) and
	 * its arguments as written.
	 */
	private static String targetKey(PropertyCall call, Action action) {
		Property p = call.getProperty();
		if (p == null || p.eIsProxy() || !(p.eContainer() instanceof Actor owner)) {
			return text(call);
		}
		StringBuilder key = new StringBuilder();
		if (owner != EcoreUtil2.getContainerOfType(action, Actor.class)) {
			key.append(owner.getName()).append('.');
		}
		key.append(p.getName()).append('(');
		for (int i = 0; i < call.getArguments().size(); i++) {
			key.append(i == 0 ? "" : ", ").append(text(call.getArguments().get(i)));
		}
		return key.append(')').toString();
	}

	private static String text(EObject e) {
		return NodeModelUtils.getTokenText(NodeModelUtils.findActualNodeFor(e)).replaceAll("\\s+", "");
	}

	private static int indexIn(EObject e) {
		Object value = e.eContainer().eGet(e.eContainmentFeature());
		return value instanceof java.util.List<?> list ? list.indexOf(e) : -1;
	}

	private static String analysisCode(Postconditions.Problem problem) {
		return problem.badValue() ? ActorIssueCodes.EFFECT_VALUE : ActorIssueCodes.POST_NOT_EFFECT;
	}

	@Check(CheckType.NORMAL)
	public void checkOneActorOfEachKind(Actor actor) {
		if (actor.eResource() == null) {
			return;
		}
		IResourceDescriptions index = indexProvider.getResourceDescriptions(actor.eResource());
		for (IEObjectDescription d : index.getExportedObjectsByType(P.getActor())) {
			if (d.getEObjectURI().equals(EcoreUtil.getURI(actor))) {
				continue;
			}
			EObject other = EcoreUtil.resolve(d.getEObjectOrProxy(), actor.eResource().getResourceSet());
			if (other instanceof Actor o && o.getKind() == actor.getKind()) {
				error("an application has one " + actor.getKind().getLiteral() + ", but '" + o.getName() + "' in "
						+ d.getEObjectURI().lastSegment() + " is one too", actor, P.getNamedElement_Name(), ActorIssueCodes.DUPLICATE_KIND);
				return;
			}
		}
	}
}
