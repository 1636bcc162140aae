package org.triad.fuzz;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.function.Supplier;

import org.eclipse.lsp4j.*;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.eclipse.lsp4j.services.TextDocumentService;
import org.eclipse.lsp4j.services.WorkspaceService;

/**
 * Every request of the protocol's text-document and workspace services that takes a document and
 * a place in it, as an editor sends them: the ones the server advertises and the ones it does not
 * (an editor may send those too). Each answer must be a result or a proper error, see
 * {@link LanguageServerSession#answer}.
 */
final class EditorRequests {
	private EditorRequests() {
	}

	/** The requests, by LSP method name, for the document {@code uri} at {@code at} (and the range up to {@code to}). */
	static Map<String, Supplier<CompletableFuture<?>>> at(LanguageServerSession s, String uri, Position at, Position to) {
		TextDocumentService docs = s.server.getTextDocumentService();
		WorkspaceService ws = s.server.getWorkspaceService();
		TextDocumentIdentifier doc = new TextDocumentIdentifier(uri);
		Range range = new Range(at, to);
		FormattingOptions options = new FormattingOptions(2, true);
		Map<String, Supplier<CompletableFuture<?>>> r = new LinkedHashMap<>();
		r.put("textDocument/completion", () -> docs.completion(new CompletionParams(doc, at)));
		r.put("completionItem/resolve", () -> docs.resolveCompletionItem(new CompletionItem("loc")));
		r.put("textDocument/hover", () -> docs.hover(new HoverParams(doc, at)));
		r.put("textDocument/signatureHelp", () -> docs.signatureHelp(new SignatureHelpParams(doc, at)));
		r.put("textDocument/declaration", () -> docs.declaration(new DeclarationParams(doc, at)));
		r.put("textDocument/definition", () -> docs.definition(new DefinitionParams(doc, at)));
		r.put("textDocument/typeDefinition", () -> docs.typeDefinition(new TypeDefinitionParams(doc, at)));
		r.put("textDocument/implementation", () -> docs.implementation(new ImplementationParams(doc, at)));
		r.put("textDocument/references", () -> docs.references(new ReferenceParams(doc, at, new ReferenceContext(true))));
		r.put("textDocument/documentHighlight", () -> docs.documentHighlight(new DocumentHighlightParams(doc, at)));
		r.put("textDocument/documentSymbol", () -> docs.documentSymbol(new DocumentSymbolParams(doc)));
		r.put("textDocument/codeAction", () -> docs.codeAction(new CodeActionParams(doc, range, new CodeActionContext(List.of()))));
		r.put("textDocument/codeLens", () -> docs.codeLens(new CodeLensParams(doc)));
		r.put("textDocument/formatting", () -> docs.formatting(new DocumentFormattingParams(doc, options)));
		r.put("textDocument/rangeFormatting", () -> docs.rangeFormatting(new DocumentRangeFormattingParams(doc, options, range)));
		r.put("textDocument/onTypeFormatting", () -> docs.onTypeFormatting(new DocumentOnTypeFormattingParams(doc, options, at, ";")));
		r.put("textDocument/rename", () -> docs.rename(new RenameParams(doc, at, "renamed")));
		r.put("textDocument/prepareRename", () -> docs.prepareRename(new PrepareRenameParams(doc, at)));
		r.put("textDocument/linkedEditingRange", () -> docs.linkedEditingRange(new LinkedEditingRangeParams(doc, at)));
		r.put("textDocument/documentLink", () -> docs.documentLink(new DocumentLinkParams(doc)));
		r.put("textDocument/documentColor", () -> docs.documentColor(new DocumentColorParams(doc)));
		r.put("textDocument/foldingRange", () -> docs.foldingRange(new FoldingRangeRequestParams(doc)));
		r.put("textDocument/selectionRange", () -> docs.selectionRange(new SelectionRangeParams(doc, List.of(at))));
		r.put("textDocument/prepareCallHierarchy", () -> docs.prepareCallHierarchy(new CallHierarchyPrepareParams(doc, at)));
		r.put("textDocument/prepareTypeHierarchy", () -> docs.prepareTypeHierarchy(new TypeHierarchyPrepareParams(doc, at)));
		r.put("textDocument/semanticTokens/full", () -> docs.semanticTokensFull(new SemanticTokensParams(doc)));
		r.put("textDocument/semanticTokens/full/delta", () -> docs.semanticTokensFullDelta(new SemanticTokensDeltaParams(doc, "0")));
		r.put("textDocument/semanticTokens/range", () -> docs.semanticTokensRange(new SemanticTokensRangeParams(doc, range)));
		r.put("textDocument/moniker", () -> docs.moniker(new MonikerParams(doc, at)));
		r.put("textDocument/inlayHint", () -> docs.inlayHint(new InlayHintParams(doc, range)));
		r.put("textDocument/inlineValue", () -> docs.inlineValue(new InlineValueParams(doc, range, new InlineValueContext(0, range))));
		r.put("textDocument/diagnostic", () -> docs.diagnostic(new DocumentDiagnosticParams(doc)));
		r.put("textDocument/willSaveWaitUntil", () -> docs.willSaveWaitUntil(new WillSaveTextDocumentParams(doc, TextDocumentSaveReason.Manual)));
		r.put("workspace/symbol", () -> ws.symbol(new WorkspaceSymbolParams("Is")));
		r.put("workspace/executeCommand", () -> ws.executeCommand(new ExecuteCommandParams("triad.unknown", List.of())));
		return r;
	}

	/** The LSP methods the server's capabilities advertise (requests taking a document). */
	static List<String> advertised(ServerCapabilities c) {
		Map<String, Object> byMethod = new LinkedHashMap<>();
		byMethod.put("textDocument/completion", c.getCompletionProvider());
		byMethod.put("textDocument/hover", either(c.getHoverProvider()));
		byMethod.put("textDocument/signatureHelp", c.getSignatureHelpProvider());
		byMethod.put("textDocument/declaration", either(c.getDeclarationProvider()));
		byMethod.put("textDocument/definition", either(c.getDefinitionProvider()));
		byMethod.put("textDocument/typeDefinition", either(c.getTypeDefinitionProvider()));
		byMethod.put("textDocument/implementation", either(c.getImplementationProvider()));
		byMethod.put("textDocument/references", either(c.getReferencesProvider()));
		byMethod.put("textDocument/documentHighlight", either(c.getDocumentHighlightProvider()));
		byMethod.put("textDocument/documentSymbol", either(c.getDocumentSymbolProvider()));
		byMethod.put("textDocument/codeAction", either(c.getCodeActionProvider()));
		byMethod.put("textDocument/codeLens", c.getCodeLensProvider());
		byMethod.put("textDocument/formatting", either(c.getDocumentFormattingProvider()));
		byMethod.put("textDocument/rangeFormatting", either(c.getDocumentRangeFormattingProvider()));
		byMethod.put("textDocument/onTypeFormatting", c.getDocumentOnTypeFormattingProvider());
		byMethod.put("textDocument/rename", either(c.getRenameProvider()));
		byMethod.put("textDocument/linkedEditingRange", either(c.getLinkedEditingRangeProvider()));
		byMethod.put("textDocument/documentLink", c.getDocumentLinkProvider());
		byMethod.put("textDocument/documentColor", either(c.getColorProvider()));
		byMethod.put("textDocument/foldingRange", either(c.getFoldingRangeProvider()));
		byMethod.put("textDocument/selectionRange", either(c.getSelectionRangeProvider()));
		byMethod.put("textDocument/prepareCallHierarchy", either(c.getCallHierarchyProvider()));
		byMethod.put("textDocument/prepareTypeHierarchy", either(c.getTypeHierarchyProvider()));
		byMethod.put("textDocument/semanticTokens/full", c.getSemanticTokensProvider());
		byMethod.put("textDocument/moniker", either(c.getMonikerProvider()));
		byMethod.put("textDocument/inlayHint", either(c.getInlayHintProvider()));
		byMethod.put("textDocument/inlineValue", either(c.getInlineValueProvider()));
		byMethod.put("textDocument/diagnostic", c.getDiagnosticProvider());
		byMethod.put("workspace/symbol", either(c.getWorkspaceSymbolProvider()));
		byMethod.put("workspace/executeCommand", c.getExecuteCommandProvider());
		return byMethod.entrySet().stream().filter(e -> e.getValue() != null).map(Map.Entry::getKey).toList();
	}

	/** A capability given as {@code true}/{@code false} or as options: null unless it is on. */
	private static Object either(Either<Boolean, ?> e) {
		if (e == null) {
			return null;
		}
		return e.isLeft() ? (Boolean.TRUE.equals(e.getLeft()) ? Boolean.TRUE : null) : e.getRight();
	}
}
