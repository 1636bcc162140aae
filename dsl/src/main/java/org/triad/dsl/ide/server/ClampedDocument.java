package org.triad.dsl.ide.server;

import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.jsonrpc.ResponseErrorException;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseError;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseErrorCode;
import org.eclipse.xtext.ide.server.Document;
import org.eclipse.xtext.util.ITextRegion;
import org.eclipse.xtext.util.TextRegion;

/**
 * A document that reads positions as the protocol says: a character past the end of its line means
 * the end of the line (and a line past the end, the end of the text), instead of failing the request.
 */
final class ClampedDocument extends Document {
	ClampedDocument(Document document) {
		super(document.getVersion(), document.getContents());
	}

	@Override
	public int getOffSet(Position position) {
		int lines = getLineCount();
		int line = position.getLine();
		if (line < 0 || position.getCharacter() < 0) {
			throw new ResponseErrorException(new ResponseError(ResponseErrorCode.InvalidParams, "negative position " + position, null));
		}
		if (line >= lines) {
			return getContents().length();
		}
		int length = getLineContent(line).length();
		return super.getOffSet(new Position(line, Math.min(position.getCharacter(), length)));
	}

	@Override
	public ITextRegion getTextRegion(Range range) {
		int start = getOffSet(range.getStart());
		int end = getOffSet(range.getEnd());
		return new TextRegion(Math.min(start, end), Math.abs(end - start));
	}

	@Override
	public String getSubstring(Range range) {
		ITextRegion region = getTextRegion(range);
		return getContents().substring(region.getOffset(), region.getOffset() + region.getLength());
	}
}
