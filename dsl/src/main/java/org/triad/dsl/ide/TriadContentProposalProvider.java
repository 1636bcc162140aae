package org.triad.dsl.ide;

import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.xtext.Assignment;
import org.eclipse.xtext.CrossReference;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.GrammarUtil;
import org.eclipse.xtext.Keyword;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistContext;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistEntry;
import org.eclipse.xtext.ide.editor.contentassist.IIdeContentProposalAcceptor;
import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;
import org.eclipse.xtext.naming.QualifiedName;
import org.eclipse.xtext.nodemodel.ILeafNode;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.scoping.IScope;
import org.triad.dsl.triad.Actor;
import org.triad.dsl.triad.Enumeration;
import org.triad.dsl.triad.NamedElement;
import org.triad.dsl.triad.TriadPackage;

/**
 * Completion after {@code Actor.} proposes that actor's properties and after {@code Enum.} that
 * enumeration's literals; an unqualified property call proposes the enclosing actor's own
 * properties. Xtext's default would propose every property of every actor by its qualified name,
 * because while typing, the call is not yet a model element that scoping could ask about.
 */
public class TriadContentProposalProvider extends IdeContentProposalProvider {
	private static final TriadPackage P = TriadPackage.eINSTANCE;

	@Override
	protected void _createProposals(CrossReference crossReference, ContentAssistContext context, IIdeContentProposalAcceptor acceptor) {
		if (continuesAName(context)) {
			return;
		}
		EReference ref = GrammarUtil.getReference(crossReference);
		String qualifier = qualifierBeforeDot(context);
		if (ref == P.getPropertyCall_Property()) {
			Actor actor = qualifier != null ? resolve(context, P.getPropertyCall_Actor(), qualifier, Actor.class)
					: EcoreUtil2.getContainerOfType(context.getCurrentModel(), Actor.class);
			if (actor != null) {
				propose(actor.getProperties(), context, acceptor);
			}
			return;
		}
		if (ref == P.getMemberRef_Member()) {
			// after 'DoorState.' its literals, after 'i.' the attributes of i's class
			org.triad.dsl.triad.Qualifier owner = qualifier == null ? null
					: resolve(context, P.getMemberRef_Owner(), qualifier, org.triad.dsl.triad.Qualifier.class);
			if (owner instanceof Enumeration e) {
				propose(e.getLiterals(), context, acceptor);
			} else if (owner instanceof org.triad.dsl.triad.Value v && org.triad.dsl.typing.TriadTypeSystem.typeOf(v).domainClass() != null) {
				propose(org.triad.dsl.typing.TriadTypeSystem.allAttributes(org.triad.dsl.typing.TriadTypeSystem.typeOf(v).domainClass()), context, acceptor);
			}
			return;
		}
		if (qualifier != null) {
			return; // after 'X.' only members of X make sense
		}
		super._createProposals(crossReference, context, acceptor);
	}

	/** Rules that read constructs the languages do not have (to report them well): their keywords are never proposed. */
	private static final java.util.Set<String> UNSUPPORTED_RULES = java.util.Set.of("UnsupportedStep", "StepBlock", "TaskSetting",
			"TimeConstraint", "Setting", "Moment", "Quantifier");

	@Override
	protected void _createProposals(Keyword keyword, ContentAssistContext context, IIdeContentProposalAcceptor acceptor) {
		// nothing to add after 'X.', nor a keyword that is already typed in full, nor an operator
		// right after a name being typed (that name is not finished yet)
		if (qualifierBeforeDot(context) == null && !keyword.getValue().equals(context.getPrefix()) && !continuesAName(context)
				&& !UNSUPPORTED_RULES.contains(GrammarUtil.containingRule(keyword).getName())) {
			super._createProposals(keyword, context, acceptor);
		}
	}

	/**
	 * Xtext's placeholders for literals and declared names ({@code value}, {@code "value"},
	 * {@code name}) are not proposals a model author can use: only references are offered.
	 */
	@Override
	protected void _createProposals(Assignment assignment, ContentAssistContext context, IIdeContentProposalAcceptor acceptor) {
		if (assignment.getTerminal() instanceof CrossReference) {
			super._createProposals(assignment, context, acceptor);
		}
	}

	/**
	 * Whether the cursor sits right after a letter or digit with nothing typed in this context:
	 * Xtext then also asks what could follow the partial name as if it were complete, and
	 * operators or other names do not belong directly after it.
	 */
	private static boolean continuesAName(ContentAssistContext context) {
		if (!context.getPrefix().isEmpty() || context.getRootNode() == null || context.getOffset() == 0) {
			return false;
		}
		String text = context.getRootNode().getText();
		int offset = context.getOffset();
		return offset <= text.length() && Character.isJavaIdentifierPart(text.charAt(offset - 1));
	}

	private void propose(List<? extends NamedElement> elements, ContentAssistContext context, IIdeContentProposalAcceptor acceptor) {
		for (NamedElement element : elements) {
			if (element.getName() != null && element.getName().startsWith(context.getPrefix())) {
				ContentAssistEntry entry = getProposalCreator().createProposal(element.getName(), context, ContentAssistEntry.KIND_REFERENCE,
						null);
				if (entry != null) {
					acceptor.accept(entry, getProposalPriorities().getDefaultPriority(entry));
				}
			}
		}
	}

	/** The name written just before a '.' that precedes the completion offset, or null. */
	private static String qualifierBeforeDot(ContentAssistContext context) {
		INode last = context.getLastCompleteNode();
		if (last == null || !".".equals(last.getText()) || context.getRootNode() == null) {
			return null;
		}
		ILeafNode before = NodeModelUtils.findLeafNodeAtOffset(context.getRootNode(), last.getOffset() - 1);
		while (before != null && before.isHidden()) {
			before = NodeModelUtils.findLeafNodeAtOffset(context.getRootNode(), before.getOffset() - 1);
		}
		return before == null || before.getText().isBlank() ? null : before.getText().trim();
	}

	private <T> T resolve(ContentAssistContext context, EReference ref, String name, Class<T> type) {
		EObject model = context.getCurrentModel();
		if (model == null && !context.getResource().getContents().isEmpty()) {
			model = context.getResource().getContents().get(0);
		}
		if (model == null) {
			return null;
		}
		IScope scope = getScopeProvider().getScope(model, ref);
		IEObjectDescription description = scope.getSingleElement(QualifiedName.create(name));
		if (description == null) {
			return null;
		}
		EObject object = description.getEObjectOrProxy();
		if (object.eIsProxy()) {
			object = org.eclipse.emf.ecore.util.EcoreUtil.resolve(object, context.getResource());
		}
		return type.isInstance(object) && !object.eIsProxy() ? type.cast(object) : null;
	}
}
