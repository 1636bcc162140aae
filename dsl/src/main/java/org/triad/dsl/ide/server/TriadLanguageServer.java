package org.triad.dsl.ide.server;

import org.triad.dsl.semantics.ArcModels;
import java.util.List;
import java.util.concurrent.CompletableFuture;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.DeclarationParams;
import org.eclipse.lsp4j.DocumentFormattingParams;
import org.eclipse.lsp4j.DocumentRangeFormattingParams;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.eclipse.lsp4j.TextEdit;
import org.eclipse.lsp4j.jsonrpc.ResponseErrorException;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseError;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseErrorCode;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.lsp4j.DefinitionParams;
import org.eclipse.lsp4j.DidChangeWatchedFilesRegistrationOptions;
import org.eclipse.lsp4j.FileSystemWatcher;
import org.eclipse.lsp4j.ImplementationParams;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DiagnosticSeverity;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializeResult;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.xtext.resource.IResourceDescription;
import org.eclipse.xtext.validation.Issue;
import org.eclipse.lsp4j.InitializedParams;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.LocationLink;
import org.eclipse.lsp4j.Registration;
import org.eclipse.lsp4j.RegistrationParams;
import org.eclipse.lsp4j.ServerCapabilities;
import org.eclipse.lsp4j.TypeDefinitionParams;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.eclipse.xtext.ide.server.DocumentExtensions;
import org.eclipse.xtext.resource.EObjectAtOffsetHelper;
import org.eclipse.xtext.resource.XtextResource;
import org.triad.dsl.TriadLanguages;
import org.triad.dsl.arc.Subcomponent;
import org.triad.dsl.triad.Attribute;
import org.triad.dsl.triad.DomainTypeRef;
import org.triad.dsl.triad.ObjectDeclaration;
import org.triad.dsl.triad.Parameter;
import org.triad.dsl.triad.Property;
import org.triad.dsl.triad.PropertyCall;
import org.triad.dsl.triad.SituationObject;
import org.triad.dsl.triad.TypeRef;
import org.triad.dsl.triad.ValueRef;


/**
 * Xtext's language server with what editors ask of it beyond Xtext's defaults: it watches the
 * model files on disk (so a model changed or created outside the editor is re-checked), and it
 * answers type-definition, declaration and implementation requests instead of failing them.
 */
public class TriadLanguageServer extends org.eclipse.xtext.ide.server.LanguageServerImpl {
	/** The registration id of the file watcher, so a client can tell it apart. */
	public static final String WATCHER_REGISTRATION = "triad-model-files";

	private volatile ClientCapabilities clientCapabilities;
	private volatile BuildProgress progress;

	@Override
	protected ServerCapabilities createServerCapabilities(InitializeParams params) {
		clientCapabilities = params == null ? null : params.getCapabilities();
		ServerCapabilities capabilities = super.createServerCapabilities(params);
		capabilities.setTypeDefinitionProvider(true);
		capabilities.setDeclarationProvider(true);
		capabilities.setImplementationProvider(true);
		return capabilities;
	}

	/**
	 * Xtext checks the whole workspace while it answers {@code initialize}; {@link BuildProgress} tells the
	 * editor what it is doing meanwhile and how it ended, so that a large workspace is never a silent wait.
	 */
	@Override
	public CompletableFuture<InitializeResult> initialize(InitializeParams params) {
		LanguageClient client = getLanguageClient();
		if (client == null || params == null) {
			return super.initialize(params);
		}
		BuildProgress p = new BuildProgress(client, params.getWorkDoneToken());
		progress = p;
		p.begin(workspaceName(params));
		return super.initialize(params).whenComplete((result, failure) -> p.end());
	}

	@Override
	public void afterBuild(List<IResourceDescription.Delta> deltas) {
		super.afterBuild(deltas);
		BuildProgress p = progress;
		if (p != null) {
			p.built(deltas.size());
		}
	}

	/** Counts the errors of the first check's diagnostics, which Xtext publishes once the client is initialized. */
	@Override
	protected List<Diagnostic> toDiagnostics(Iterable<? extends Issue> issues) {
		List<Diagnostic> diagnostics = super.toDiagnostics(issues);
		BuildProgress p = progress;
		if (p != null) {
			p.published((int) diagnostics.stream().filter(d -> d.getSeverity() == DiagnosticSeverity.Error).count());
		}
		return diagnostics;
	}

	private static String workspaceName(InitializeParams params) {
		if (params.getWorkspaceFolders() != null && !params.getWorkspaceFolders().isEmpty()) {
			return params.getWorkspaceFolders().get(0).getUri();
		}
		return params.getRootUri() != null ? params.getRootUri() : "the workspace";
	}

	@Override
	public void initialized(InitializedParams params) {
		super.initialized(params); // publishes the first check's diagnostics, in this thread
		BuildProgress p = progress;
		progress = null;
		if (p != null) {
			p.summarize();
		}
		if (supportsWatcherRegistration()) {
			String glob = "**/*.{" + String.join(",", TriadLanguages.EXTENSIONS) + "}";
			DidChangeWatchedFilesRegistrationOptions options = new DidChangeWatchedFilesRegistrationOptions(
					List.of(new FileSystemWatcher(Either.forLeft(glob))));
			getLanguageClient().registerCapability(
					new RegistrationParams(List.of(new Registration(WATCHER_REGISTRATION, "workspace/didChangeWatchedFiles", options))));
		}
	}

	private boolean supportsWatcherRegistration() {
		ClientCapabilities c = clientCapabilities;
		return c != null && c.getWorkspace() != null && c.getWorkspace().getDidChangeWatchedFiles() != null
				&& Boolean.TRUE.equals(c.getWorkspace().getDidChangeWatchedFiles().getDynamicRegistration());
	}

	/**
	 * The longest document formatted, in characters: Xtext's formatter takes about a minute for 5 MB and
	 * cannot be stopped midway, so a larger document is refused at once rather than cut off at the
	 * request bound ({@link GuardedRequestManager#REQUEST_BOUND}) with the formatter still running.
	 */
	public static final int MAX_FORMATTED_CHARS = 1 << 20;

	@Override
	protected List<? extends TextEdit> formatting(DocumentFormattingParams params, CancelIndicator cancelIndicator) {
		refuseLargeDocument(params.getTextDocument());
		return super.formatting(params, cancelIndicator);
	}

	@Override
	protected List<? extends TextEdit> rangeFormatting(DocumentRangeFormattingParams params, CancelIndicator cancelIndicator) {
		refuseLargeDocument(params.getTextDocument());
		return super.rangeFormatting(params, cancelIndicator);
	}

	private void refuseLargeDocument(TextDocumentIdentifier textDocument) {
		URI uri = getURI(textDocument);
		int length = getWorkspaceManager().doRead(uri, (document, resource) -> document.getContents().length());
		if (length > MAX_FORMATTED_CHARS) {
			throw new ResponseErrorException(new ResponseError(ResponseErrorCode.RequestFailed, "the document has " + length
					+ " characters; the Triad language server formats documents of at most " + MAX_FORMATTED_CHARS + " characters", null));
		}
	}

	/** The declaration of the type of the value under the cursor (a parameter's, property's, attribute's or object's class). */
	@Override
	public CompletableFuture<Either<List<? extends Location>, List<? extends LocationLink>>> typeDefinition(TypeDefinitionParams params) {
		URI uri = getURI(params.getTextDocument());
		return getRequestManager().runRead(cancel -> Either.forLeft(getWorkspaceManager().doRead(uri,
				(document, resource) -> typeLocations(uri, resource, document.getOffSet(params.getPosition())))));
	}

	/** In models a name's declaration is its definition. */
	@Override
	public CompletableFuture<Either<List<? extends Location>, List<? extends LocationLink>>> declaration(DeclarationParams params) {
		DefinitionParams definition = new DefinitionParams(params.getTextDocument(), params.getPosition());
		return definition(definition);
	}

	/**
	 * Models declare and define in one place, and what implements a robot's actions is Java code the
	 * language server does not see: the answer is the definition, so "go to implementation" still
	 * lands on the element rather than failing.
	 */
	@Override
	public CompletableFuture<Either<List<? extends Location>, List<? extends LocationLink>>> implementation(ImplementationParams params) {
		DefinitionParams definition = new DefinitionParams(params.getTextDocument(), params.getPosition());
		return definition(definition);
	}

	private List<Location> typeLocations(URI uri, XtextResource resource, int offset) {
		EObjectAtOffsetHelper elementAtOffset = getService(uri, EObjectAtOffsetHelper.class);
		DocumentExtensions documentExtensions = getService(uri, DocumentExtensions.class);
		if (resource == null || elementAtOffset == null || documentExtensions == null) {
			return List.of();
		}
		EObject element = elementAtOffset.resolveCrossReferencedElementAt(resource, offset);
		if (element == null) {
			element = elementAtOffset.resolveElementAt(resource, offset);
		}
		EObject type = typeOf(element);
		if (type == null || type.eIsProxy() || type.eResource() == null) {
			return List.of();
		}
		Location location = documentExtensions.newLocation(type);
		return location == null ? List.of() : List.of(location);
	}

	/** The class or enumeration an element's values have, or (for a subcomponent) its component type. */
	static EObject typeOf(EObject e) {
		if (e instanceof PropertyCall call) {
			return typeOf(call.getProperty());
		}
		if (e instanceof ValueRef ref) {
			return typeOf(ref.getValue());
		}
		if (e instanceof Parameter p) {
			return domainType(p.getType());
		}
		if (e instanceof Property p) {
			return domainType(p.getType());
		}
		if (e instanceof Attribute a) {
			return domainType(a.getType());
		}
		if (e instanceof SituationObject o && o.eContainer() instanceof ObjectDeclaration d) {
			return d.getType();
		}
		if (e instanceof Subcomponent s) {
			return ArcModels.type(s);
		}
		return null;
	}

	private static EObject domainType(TypeRef ref) {
		return ref instanceof DomainTypeRef d ? d.getType() : null;
	}
}
