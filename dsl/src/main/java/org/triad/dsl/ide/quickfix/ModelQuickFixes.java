package org.triad.dsl.ide.quickfix;

import java.io.File;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.lsp4j.CodeAction;
import org.eclipse.lsp4j.CodeActionKind;
import org.eclipse.lsp4j.Command;
import org.eclipse.lsp4j.CreateFile;
import org.eclipse.lsp4j.CreateFileOptions;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.ResourceOperation;
import org.eclipse.lsp4j.TextDocumentEdit;
import org.eclipse.lsp4j.TextEdit;
import org.eclipse.lsp4j.VersionedTextDocumentIdentifier;
import org.eclipse.lsp4j.WorkspaceEdit;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.eclipse.xtext.CrossReference;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.GrammarUtil;
import org.eclipse.xtext.Keyword;
import org.eclipse.xtext.ide.server.Document;
import org.eclipse.xtext.ide.server.codeActions.ICodeActionService2;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.ILeafNode;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.impl.ResourceDescriptionsProvider;
import org.eclipse.xtext.scoping.IScopeProvider;
import org.triad.dsl.ide.hover.ModelSignatures;
import org.triad.dsl.triad.DomainModel;
import org.triad.dsl.triad.Expression;
import org.triad.dsl.triad.GoalReference;
import org.triad.dsl.triad.Parameter;
import org.triad.dsl.triad.Parameterized;
import org.triad.dsl.triad.PropertyCall;
import org.triad.dsl.triad.TriadPackage;
import org.triad.dsl.triad.ValueRef;
import org.triad.dsl.typing.TriadType;
import org.triad.dsl.typing.TriadTypeSystem;
import org.triad.dsl.validation.CommonIssueCodes;
import org.triad.dsl.validation.TaskIssueCodes;

import com.google.inject.Inject;

/**
 * Quick fixes for the diagnostics model authors meet most: a misspelt goal, type, property, actor
 * or parameter ("did you mean"), a goal that does not exist yet (create its .goal file with the
 * parameters the call implies), a model without its {@code domain} line, and a call with the wrong
 * number of arguments (adjust it to the declared parameters).
 */
public class ModelQuickFixes implements ICodeActionService2 {
	private static final TriadPackage P = TriadPackage.eINSTANCE;
	private static final Set<String> NAME_CODES = Set.of(CommonIssueCodes.UNKNOWN_GOAL, CommonIssueCodes.UNKNOWN_TYPE,
			CommonIssueCodes.UNKNOWN_PROPERTY, CommonIssueCodes.UNKNOWN_ACTOR, CommonIssueCodes.UNKNOWN_VALUE,
			CommonIssueCodes.UNKNOWN_ENUMERATION, CommonIssueCodes.UNKNOWN_LITERAL, CommonIssueCodes.UNKNOWN_ATTRIBUTE,
			CommonIssueCodes.UNKNOWN_DOMAIN);

	@Inject
	private IScopeProvider scopes;

	@Inject
	private ResourceDescriptionsProvider index;

	@Override
	public List<Either<Command, CodeAction>> getCodeActions(Options options) {
		List<String> only = options.getCodeActionParams().getContext().getOnly();
		if (only != null && !only.isEmpty() && only.stream().noneMatch(k -> k.startsWith(CodeActionKind.QuickFix))) {
			return List.of();
		}
		List<Either<Command, CodeAction>> result = new ArrayList<>();
		for (Diagnostic d : options.getCodeActionParams().getContext().getDiagnostics()) {
			String code = d.getCode() == null ? null : d.getCode().isLeft() ? d.getCode().getLeft() : String.valueOf(d.getCode().getRight());
			if (code == null) {
				continue;
			}
			List<CodeAction> fixes = options.getLanguageServerAccess().doSyncRead(options.getURI(),
					ctx -> fixes(code, d, ctx.getDocument(), (XtextResource) ctx.getResource(), options.getURI()));
			fixes.forEach(f -> result.add(Either.forRight(f)));
		}
		return result;
	}

	List<CodeAction> fixes(String code, Diagnostic d, Document document, XtextResource resource, String uri) {
		List<CodeAction> fixes = new ArrayList<>();
		int offset = document.getOffSet(d.getRange().getStart());
		if (NAME_CODES.contains(code)) {
			didYouMean(d, resource, offset, uri, fixes);
			if (code.equals(CommonIssueCodes.UNKNOWN_GOAL)) {
				createGoal(d, resource, offset, uri, fixes);
			}
		} else if (code.equals(CommonIssueCodes.SYNTAX)) {
			insertDomain(d, document, resource, uri, fixes);
		} else if (code.equals(TaskIssueCodes.ARGUMENT_COUNT) || code.equals(CommonIssueCodes.ARGUMENT_COUNT)) {
			adjustArguments(d, document, resource, offset, uri, fixes);
		}
		return fixes;
	}

	/** The cross-reference written at {@code offset}: its owner, reference and node. */
	record Reference(EObject owner, EReference reference, INode node) {
	}

	static Reference referenceAt(XtextResource resource, int offset) {
		if (resource.getParseResult() == null) {
			return null;
		}
		ILeafNode leaf = NodeModelUtils.findLeafNodeAtOffset(resource.getParseResult().getRootNode(), offset);
		for (INode n = leaf; n != null; n = n.getParent()) {
			if (n.getGrammarElement() instanceof CrossReference ref) {
				EObject owner = NodeModelUtils.findActualSemanticObjectFor(n);
				EReference feature = GrammarUtil.getReference(ref);
				return owner == null || feature == null ? null : new Reference(owner, feature, n);
			}
		}
		return null;
	}

	private void didYouMean(Diagnostic d, XtextResource resource, int offset, String uri, List<CodeAction> fixes) {
		Reference ref = referenceAt(resource, offset);
		if (ref == null) {
			return;
		}
		String written = NodeModelUtils.getTokenText(ref.node());
		String lastSegment = written.substring(written.lastIndexOf('.') + 1);
		Set<String> known = new LinkedHashSet<>();
		for (IEObjectDescription e : scopes.getScope(ref.owner(), ref.reference()).getAllElements()) {
			known.add(written.contains(".") ? e.getName().toString() : e.getName().getLastSegment());
		}
		for (String name : NameSuggestions.closest(written.contains(".") ? written : lastSegment, known)) {
			fixes.add(fix("Change to '" + name + "'", d, uri, List.of(new TextEdit(d.getRange(), name))));
		}
	}

	private void createGoal(Diagnostic d, XtextResource resource, int offset, String uri, List<CodeAction> fixes) {
		Reference ref = referenceAt(resource, offset);
		if (ref == null || !(ref.owner() instanceof GoalReference call)) {
			return;
		}
		String name = NodeModelUtils.getTokenText(ref.node());
		DomainModel model = EcoreUtil2.getContainerOfType(call, DomainModel.class);
		List<INode> domainNodes = model == null ? List.of() : NodeModelUtils.findNodesForFeature(model, P.getDomainModel_Domain());
		if (domainNodes.isEmpty() || !name.matches("[A-Za-z_]\\w*")) {
			return;
		}
		URI target = resource.getURI().trimSegments(1).appendSegment(name + ".goal");
		if (target.isFile() && new File(target.toFileString()).exists()) {
			return; // the file is there; the goal in it is misspelt or missing, which 'did you mean' covers
		}
		String text = "domain " + NodeModelUtils.getTokenText(domainNodes.get(0)) + ";\n\ngoal " + name + "(" + impliedParameters(call)
				+ ") {\n  true\n}\n";
		String targetUri = uri.substring(0, uri.lastIndexOf('/') + 1) + name + ".goal";
		WorkspaceEdit edit = new WorkspaceEdit();
		CreateFile create = new CreateFile(targetUri, new CreateFileOptions(false, true));
		TextDocumentEdit content = new TextDocumentEdit(new VersionedTextDocumentIdentifier(targetUri, null),
				List.of(Either.<TextEdit, org.eclipse.lsp4j.SnippetTextEdit>forLeft(new TextEdit(new Range(new Position(0, 0), new Position(0, 0)), text))));
		edit.setDocumentChanges(List.of(Either.<TextDocumentEdit, ResourceOperation>forRight(create), Either.forLeft(content)));
		CodeAction action = new CodeAction("Create goal '" + name + "' in " + name + ".goal");
		action.setKind(CodeActionKind.QuickFix);
		action.setDiagnostics(List.of(d));
		action.setEdit(edit);
		fixes.add(action);
	}

	/** Parameters for a goal from a call's arguments: a task parameter's type and name, or a literal's type. */
	static String impliedParameters(GoalReference call) {
		List<String> params = new ArrayList<>();
		Set<String> used = new LinkedHashSet<>();
		int i = 0;
		for (Expression arg : call.getArguments()) {
			i++;
			TriadType type = TriadTypeSystem.typeOf(arg);
			String typeName = type.isUnknown() ? "boolean" : type.display();
			String name = arg instanceof ValueRef v && v.getValue() != null && !v.getValue().eIsProxy() ? v.getValue().getName() : "p" + i;
			while (!used.add(name)) {
				name = name + i;
			}
			params.add(typeName + " " + name);
		}
		return String.join(", ", params);
	}

	private void insertDomain(Diagnostic d, Document document, XtextResource resource, String uri, List<CodeAction> fixes) {
		String ext = resource.getURI().fileExtension();
		if (!List.of("actor", "goal", "task", "state").contains(ext) || resource.getParseResult() == null) {
			return;
		}
		ILeafNode first = null;
		for (ILeafNode leaf : resource.getParseResult().getRootNode().getLeafNodes()) {
			if (!leaf.isHidden()) {
				first = leaf;
				break;
			}
		}
		if (first == null || first.getGrammarElement() instanceof Keyword k && k.getValue().equals("domain")) {
			return;
		}
		int at = document.getContents().lastIndexOf('\n', first.getOffset() - 1) + 1;
		Position position = document.getPosition(at);
		Set<String> diagrams = new LinkedHashSet<>();
		for (IEObjectDescription cd : index.getResourceDescriptions(resource).getExportedObjectsByType(P.getClassDiagram())) {
			diagrams.add(cd.getName().toString());
		}
		for (String cd : diagrams) {
			fixes.add(fix("Insert 'domain " + cd + ";'", d, uri, List.of(new TextEdit(new Range(position, position), "domain " + cd + ";\n\n"))));
		}
	}

	private void adjustArguments(Diagnostic d, Document document, XtextResource resource, int offset, String uri, List<CodeAction> fixes) {
		Reference ref = referenceAt(resource, offset);
		if (ref == null) {
			return;
		}
		EObject callObject = ref.owner();
		Parameterized callee;
		List<Expression> args;
		if (callObject instanceof GoalReference g && g.getGoal() != null && !g.getGoal().eIsProxy()) {
			callee = g.getGoal();
			args = g.getArguments();
		} else if (callObject instanceof PropertyCall c && c.getProperty() != null && !c.getProperty().eIsProxy()) {
			callee = c.getProperty();
			args = c.getArguments();
		} else {
			return;
		}
		ICompositeNode node = NodeModelUtils.findActualNodeFor(callObject);
		int open = -1;
		int close = -1;
		for (ILeafNode leaf : node.getLeafNodes()) {
			if (leaf.getGrammarElement() instanceof Keyword k) {
				if (open < 0 && k.getValue().equals("(")) {
					open = leaf.getOffset();
				} else if (k.getValue().equals(")")) {
					close = leaf.getOffset();
				}
			}
		}
		if (open < 0 || close < open) {
			return;
		}
		List<String> values = new ArrayList<>();
		Set<String> usedNames = new LinkedHashSet<>();
		for (Expression a : args) {
			usedNames.add(ModelSignatures.text(a));
		}
		for (int i = 0; i < callee.getParameters().size(); i++) {
			values.add(i < args.size() ? ModelSignatures.text(args.get(i)) : fillIn(callee.getParameters().get(i), callObject, usedNames));
		}
		String newArgs = String.join(", ", values);
		String title = "Change to " + callee.getName() + "(" + newArgs + ")";
		fixes.add(fix(title, d, uri, List.of(new TextEdit(new Range(document.getPosition(open + 1), document.getPosition(close)), newArgs))));
	}

	/**
	 * A value for a missing argument: an unused parameter in scope of the parameter's type (a task's
	 * or action's own parameters), else the parameter's name for the author to replace.
	 */
	private static String fillIn(Parameter wanted, EObject call, Set<String> used) {
		Parameterized owner = EcoreUtil2.getContainerOfType(call, Parameterized.class);
		TriadType type = TriadTypeSystem.typeOf(wanted.getType());
		if (owner != null) {
			for (Parameter p : owner.getParameters()) {
				if (!used.contains(p.getName()) && TriadTypeSystem.isAssignable(type, TriadTypeSystem.typeOf(p.getType()))) {
					used.add(p.getName());
					return p.getName();
				}
			}
		}
		return wanted.getName();
	}

	private static CodeAction fix(String title, Diagnostic d, String uri, List<TextEdit> edits) {
		CodeAction action = new CodeAction(title);
		action.setKind(CodeActionKind.QuickFix);
		action.setDiagnostics(List.of(d));
		action.setEdit(new WorkspaceEdit(Map.of(uri, edits)));
		return action;
	}
}
