package org.triad.dsl.ide;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.lsp4j.SemanticTokenModifiers;
import org.eclipse.lsp4j.SemanticTokenTypes;
import org.eclipse.xtext.Assignment;
import org.eclipse.xtext.CrossReference;
import org.eclipse.xtext.GrammarUtil;
import org.eclipse.xtext.Keyword;
import org.eclipse.xtext.RuleCall;
import org.eclipse.xtext.TerminalRule;
import org.eclipse.xtext.ide.editor.syntaxcoloring.IHighlightedPositionAcceptor;
import org.eclipse.xtext.ide.editor.syntaxcoloring.ISemanticHighlightingCalculator;
import org.eclipse.xtext.nodemodel.ILeafNode;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.util.CancelIndicator;
import org.triad.dsl.arc.ArcPort;
import org.triad.dsl.arc.AutomatonState;
import org.triad.dsl.arc.ComponentType;
import org.triad.dsl.arc.ConfigParameter;
import org.triad.dsl.arc.Subcomponent;
import org.triad.dsl.triad.Action;
import org.triad.dsl.triad.Actor;
import org.triad.dsl.triad.Attribute;
import org.triad.dsl.triad.ClassDiagram;
import org.triad.dsl.triad.DomainClass;
import org.triad.dsl.triad.EnumLiteral;
import org.triad.dsl.triad.Enumeration;
import org.triad.dsl.triad.Goal;
import org.triad.dsl.triad.Parameter;
import org.triad.dsl.triad.Property;
import org.triad.dsl.triad.Situation;
import org.triad.dsl.triad.SituationObject;
import org.triad.dsl.triad.Task;

/**
 * Semantic tokens: word keywords, and every name, declared or referenced, by what it names (goal,
 * task, property, action, type, parameter, object, ...), so a reference to a property and one to a
 * parameter look different even where the grammar alone cannot tell them apart.
 */
public class ModelSemanticTokens implements ISemanticHighlightingCalculator {
	@Override
	public void provideHighlightingFor(XtextResource resource, IHighlightedPositionAcceptor acceptor, CancelIndicator cancel) {
		if (resource == null || resource.getParseResult() == null) {
			return;
		}
		for (ILeafNode leaf : resource.getParseResult().getRootNode().getLeafNodes()) {
			if (cancel != null && cancel.isCanceled()) {
				return;
			}
			if (leaf.isHidden() || leaf.getLength() == 0) {
				continue;
			}
			EObject grammar = leaf.getGrammarElement();
			if (grammar instanceof Keyword k) {
				if (Character.isLetter(k.getValue().charAt(0))) {
					acceptor.addPosition(leaf.getOffset(), leaf.getLength(), SemanticTokenTypes.Keyword);
				}
				continue;
			}
			if (grammar instanceof RuleCall call && call.getRule() instanceof TerminalRule t && !"ID".equals(t.getName())) {
				if ("STRING".equals(t.getName())) {
					acceptor.addPosition(leaf.getOffset(), leaf.getLength(), SemanticTokenTypes.String);
				} else if ("INT".equals(t.getName())) {
					acceptor.addPosition(leaf.getOffset(), leaf.getLength(), SemanticTokenTypes.Number);
				}
				continue;
			}
			if (!Character.isJavaIdentifierStart(leaf.getText().charAt(0))) {
				continue;
			}
			String[] ids = nameTokenType(leaf);
			if (ids != null) {
				acceptor.addPosition(leaf.getOffset(), leaf.getLength(), ids);
			}
		}
	}

	/**
	 * A name's token type: of the element it refers to, or of the element it declares (with the
	 * declaration modifier). A name inside a qualified name or a data-type rule sits a few nodes
	 * below the cross-reference or assignment that gives it meaning.
	 */
	private static String[] nameTokenType(ILeafNode leaf) {
		INode node = leaf;
		for (int depth = 0; node != null && depth < 4; depth++, node = node.getParent()) {
			EObject grammar = node.getGrammarElement();
			if (grammar instanceof CrossReference ref) {
				EObject target = referenced(node, ref);
				String type = target == null ? null : tokenType(target);
				return type == null ? null : new String[] { type };
			}
			Assignment assignment = grammar == null ? null : GrammarUtil.containingAssignment(grammar);
			if (assignment != null) {
				if (!"name".equals(assignment.getFeature())) {
					return null;
				}
				EObject declared = NodeModelUtils.findActualSemanticObjectFor(node);
				String type = declared == null ? null : tokenType(declared);
				return type == null ? null : new String[] { type, SemanticTokenModifiers.Declaration };
			}
		}
		return null;
	}

	private static EObject referenced(INode node, CrossReference ref) {
		EObject owner = NodeModelUtils.findActualSemanticObjectFor(node);
		EReference feature = GrammarUtil.getReference(ref);
		if (owner == null || feature == null || feature.isMany() || !feature.getEContainingClass().isSuperTypeOf(owner.eClass())) {
			return null;
		}
		Object value = owner.eGet(feature, true);
		return value instanceof EObject target && !target.eIsProxy() ? target : null;
	}

	/** The LSP token type for a name of this kind of element. */
	static String tokenType(EObject e) {
		if (e instanceof Goal || e instanceof Task) {
			return SemanticTokenTypes.Function;
		}
		if (e instanceof Property || e instanceof Attribute) {
			return SemanticTokenTypes.Property;
		}
		if (e instanceof Action) {
			return SemanticTokenTypes.Method;
		}
		if (e instanceof DomainClass || e instanceof ComponentType) {
			return SemanticTokenTypes.Class;
		}
		if (e instanceof Enumeration) {
			return SemanticTokenTypes.Enum;
		}
		if (e instanceof EnumLiteral || e instanceof AutomatonState) {
			return SemanticTokenTypes.EnumMember;
		}
		if (e instanceof Parameter || e instanceof ConfigParameter) {
			return SemanticTokenTypes.Parameter;
		}
		if (e instanceof SituationObject || e instanceof Subcomponent) {
			return SemanticTokenTypes.Variable;
		}
		if (e instanceof Actor || e instanceof ClassDiagram || e instanceof Situation) {
			return SemanticTokenTypes.Namespace;
		}
		if (e instanceof ArcPort) {
			return SemanticTokenTypes.Property;
		}
		return null;
	}
}
