package org.triad.dsl.ide;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ExecutionException;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.lsp4j.WorkspaceEdit;
import org.eclipse.lsp4j.jsonrpc.ResponseErrorException;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseError;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseErrorCode;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.ide.server.rename.IRenameService2;
import org.eclipse.xtext.ide.server.rename.RenameService2;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.impl.ResourceDescriptionsProvider;
import org.eclipse.xtext.util.SimpleAttributeResolver;
import org.triad.dsl.arc.ArcNamedElement;
import org.triad.dsl.triad.Action;
import org.triad.dsl.triad.Actor;
import org.triad.dsl.triad.Attribute;
import org.triad.dsl.triad.ClassDiagram;
import org.triad.dsl.triad.DomainClass;
import org.triad.dsl.triad.DomainType;
import org.triad.dsl.triad.EnumLiteral;
import org.triad.dsl.triad.Enumeration;
import org.triad.dsl.triad.Goal;
import org.triad.dsl.triad.Parameter;
import org.triad.dsl.triad.Parameterized;
import org.triad.dsl.triad.Property;
import org.triad.dsl.triad.Situation;
import org.triad.dsl.triad.SituationObject;
import org.triad.dsl.triad.Task;
import org.triad.dsl.triad.TriadPackage;
import org.triad.dsl.typing.TriadTypeSystem;

import com.google.inject.Inject;

/**
 * Rename that refuses a new name which is not a name, or which another element already has where
 * both would be visible (a property renamed to its actor's other property, a goal to another goal,
 * a parameter to another parameter of the same goal): the editor shows the reason instead of a
 * rename that breaks the models.
 */
public class ModelRenameService extends RenameService2 {
	private static final TriadPackage P = TriadPackage.eINSTANCE;
	private static final Set<String> KEYWORDS = Set.of("domain", "robot", "world", "property", "action", "pre", "post",
			"goal", "task", "state", "classdiagram", "class", "abstract", "extends", "enum", "true", "false", "boolean", "int", "double",
			"String", "component", "port", "in", "out", "automaton", "initial", "package", "import", "faults",
			// reserved in tasks and goals so that constructs they do not have get one finding (task.no-*, goal.no-quantifier)
			"if", "else", "while", "forall", "exists", "priority", "before", "after");

	@Inject
	private ResourceDescriptionsProvider index;

	/**
	 * Refuses a bad name with a request-failed error carrying the reason, before Xtext's rename
	 * starts: an issue raised inside it would reach the editor as an internal error.
	 */
	@Override
	public WorkspaceEdit rename(IRenameService2.Options options) {
		String uri = options.getRenameParams().getTextDocument().getUri();
		String newName = options.getRenameParams().getNewName();
		String problem;
		try {
			problem = options.getLanguageServerAccess().doRead(uri, ctx -> {
				if (!(ctx.getResource() instanceof XtextResource resource)) {
					return null;
				}
				EObject element = getElementAtOffset(resource, ctx.getDocument(), options.getRenameParams().getPosition());
				return element == null || element.eIsProxy() ? null : problem(element, newName);
			}).get();
		} catch (InterruptedException e) {
			Thread.currentThread().interrupt();
			throw new ResponseErrorException(new ResponseError(ResponseErrorCode.RequestCancelled, "rename interrupted", null));
		} catch (ExecutionException e) {
			problem = null; // Xtext's rename reports what went wrong reading the document
		}
		if (problem != null) {
			throw new ResponseErrorException(new ResponseError(ResponseErrorCode.RequestFailed, problem, null));
		}
		return super.rename(options);
	}

	/** Why {@code element} cannot be called {@code newName}, or null. */
	String problem(EObject element, String newName) {
		if (newName == null || !newName.matches("[A-Za-z_][A-Za-z0-9_]*")) {
			return "'" + newName + "' is not a name: use letters, digits and '_', starting with a letter";
		}
		if (KEYWORDS.contains(newName)) {
			return "'" + newName + "' is a keyword of the Triad languages";
		}
		String oldName = SimpleAttributeResolver.NAME_RESOLVER.apply(element);
		if (newName.equals(oldName)) {
			return null;
		}
		for (EObject other : rivals(element)) {
			if (other != element && newName.equals(SimpleAttributeResolver.NAME_RESOLVER.apply(other))) {
				return "cannot rename '" + oldName + "' to '" + newName + "': " + describe(other, newName);
			}
		}
		for (IEObjectDescription other : applicationWide(element)) {
			if (newName.equals(other.getName().getLastSegment()) && !other.getEObjectURI().equals(org.eclipse.emf.ecore.util.EcoreUtil.getURI(element))) {
				return "cannot rename '" + oldName + "' to '" + newName + "': the application already has " + other.getEClass().getName().toLowerCase()
						+ " '" + newName + "'";
			}
		}
		return null;
	}

	/** Elements whose names share a namespace with the element's, found in its own model. */
	private static List<EObject> rivals(EObject e) {
		List<EObject> result = new ArrayList<>();
		if (e instanceof Property || e instanceof Action) {
			Actor actor = EcoreUtil2.getContainerOfType(e, Actor.class);
			if (actor != null) {
				result.addAll(actor.getProperties());
				result.addAll(actor.getActions());
			}
		} else if (e instanceof Parameter p && p.eContainer() instanceof Parameterized owner) {
			result.addAll(owner.getParameters());
		} else if (e instanceof Attribute a && a.eContainer() instanceof DomainClass c) {
			result.addAll(TriadTypeSystem.allAttributes(c));
		} else if (e instanceof EnumLiteral l && l.eContainer() instanceof Enumeration en) {
			result.addAll(en.getLiterals());
		} else if (e instanceof DomainType t && t.eContainer() instanceof ClassDiagram cd) {
			result.addAll(cd.getTypes());
		} else if (e instanceof SituationObject o) {
			Situation s = EcoreUtil2.getContainerOfType(o, Situation.class);
			if (s != null) {
				result.addAll(EcoreUtil2.getAllContentsOfType(s, SituationObject.class));
			}
		} else if (e instanceof ArcNamedElement && e.eContainer() != null) {
			for (EObject sibling : e.eContainer().eContents()) {
				result.add(sibling);
				result.addAll(sibling.eContents());
			}
		}
		return result;
	}

	/** Names the whole application shares: class diagrams, actors, goals, tasks and situations. */
	private Iterable<IEObjectDescription> applicationWide(EObject e) {
		if (!(e instanceof ClassDiagram || e instanceof Actor || e instanceof Goal || e instanceof Task || e instanceof Situation)
				|| e.eResource() == null || e.eResource().getResourceSet() == null) {
			return List.of();
		}
		List<IEObjectDescription> result = new ArrayList<>();
		var descriptions = index.getResourceDescriptions(e.eResource());
		for (var type : List.of(P.getClassDiagram(), P.getActor(), P.getGoal(), P.getTask(), P.getSituation())) {
			descriptions.getExportedObjectsByType(type).forEach(result::add);
		}
		return result;
	}

	/** "robot Courier already has property 'carries'" */
	private static String describe(EObject other, String name) {
		String kind = other instanceof Property ? "property" : other instanceof Action ? "action" : other instanceof Parameter ? "parameter"
				: other instanceof Attribute ? "attribute" : other instanceof EnumLiteral ? "literal" : other instanceof DomainType ? "type"
						: other instanceof SituationObject ? "object" : "element";
		EObject owner = other instanceof SituationObject ? EcoreUtil2.getContainerOfType(other, Situation.class) : other.eContainer();
		String ownerName = owner == null ? null : SimpleAttributeResolver.NAME_RESOLVER.apply(owner);
		String ownerKind = owner instanceof Actor a ? a.getKind().getLiteral() + " " : owner instanceof Parameterized p ? org.triad.dsl.ide.hover.ModelSignatures.kind(p) + " "
				: owner instanceof DomainClass ? "class " : owner instanceof Enumeration ? "enum " : owner instanceof ClassDiagram ? "classdiagram "
						: owner instanceof Situation ? "state " : "";
		return (ownerName == null ? "the model" : ownerKind + ownerName) + " already has " + kind + " '" + name + "'";
	}
}
