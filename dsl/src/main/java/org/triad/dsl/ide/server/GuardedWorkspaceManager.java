package org.triad.dsl.ide.server;

import org.eclipse.emf.common.util.URI;
import org.eclipse.lsp4j.jsonrpc.ResponseErrorException;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseError;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseErrorCode;
import org.eclipse.xtext.ide.server.Document;
import org.eclipse.xtext.ide.server.ProjectManager;
import org.eclipse.xtext.ide.server.WorkspaceManager;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.xbase.lib.Functions.Function2;

/**
 * Xtext's workspace manager, for requests about documents the server does not know: one outside the
 * workspace, or not a model file it could read, is refused with "invalid params" naming it, where
 * Xtext would fail with a null pointer; and positions are read as the protocol says ({@link ClampedDocument}).
 */
public class GuardedWorkspaceManager extends WorkspaceManager {
	@Override
	public <T> T doRead(URI uri, Function2<? super Document, ? super XtextResource, ? extends T> work) {
		URI resourceUri = uri.trimFragment();
		ProjectManager project = getProjectManager(resourceUri);
		if (project == null) {
			throw unknown(uri, "it is outside the workspace");
		}
		if (!isDocumentOpen(resourceUri) && project.getResourceSet().getResource(resourceUri, false) == null) {
			throw unknown(uri, "it is neither open nor a model file of the workspace");
		}
		return super.doRead(uri, work);
	}

	@Override
	protected Document getDocument(XtextResource resource) {
		if (resource == null || resource.getParseResult() == null) {
			throw unknown(resource == null ? null : resource.getURI(), "it is neither open nor a model file of the workspace");
		}
		return new ClampedDocument(super.getDocument(resource));
	}

	private static ResponseErrorException unknown(URI uri, String why) {
		return new ResponseErrorException(new ResponseError(ResponseErrorCode.InvalidParams,
				"unknown document " + uri + ": " + why, null));
	}
}
