package org.triad.dsl.ide.server;

import java.io.ByteArrayOutputStream;
import java.io.Closeable;
import java.io.IOException;
import java.io.InputStream;
import java.io.InterruptedIOException;
import java.io.StringReader;
import java.nio.channels.ClosedChannelException;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Locale;
import java.util.logging.Logger;

import org.eclipse.lsp4j.jsonrpc.JsonRpcException;
import org.eclipse.lsp4j.jsonrpc.MessageConsumer;
import org.eclipse.lsp4j.jsonrpc.MessageIssueException;
import org.eclipse.lsp4j.jsonrpc.MessageIssueHandler;
import org.eclipse.lsp4j.jsonrpc.MessageProducer;
import org.eclipse.lsp4j.jsonrpc.json.JsonRpcMethod;
import org.eclipse.lsp4j.jsonrpc.json.MessageJsonHandler;
import org.eclipse.lsp4j.jsonrpc.messages.Message;
import org.eclipse.lsp4j.jsonrpc.messages.MessageIssue;
import org.eclipse.lsp4j.jsonrpc.messages.NotificationMessage;
import org.eclipse.lsp4j.jsonrpc.messages.RequestMessage;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseErrorCode;
import org.eclipse.lsp4j.jsonrpc.validation.ReflectiveMessageValidator;

import com.google.gson.stream.JsonReader;
import com.google.gson.stream.JsonToken;

/**
 * Reads the client's messages off the stream so that no message can knock the server over or out of
 * step. LSP4J's own reader parses the content straight off the stream: a message it cannot parse
 * leaves the rest of its bytes behind, which are then read as headers, and every later message is
 * lost; a message nested 100,000 deep overflows the reader thread's stack and ends it. Here every
 * message is read whole by its {@code Content-Length} first (so the stream stays in step whatever
 * the content), and then:
 * <ul>
 * <li>content longer than {@link #MAX_CONTENT_BYTES}, nested deeper than {@link #MAX_DEPTH}, or not
 * JSON-RPC is refused with an error answer to its request (its {@code id} read leniently off the
 * text), or, for a notification, one line in the log (level INFO: the client's fault, not the server's);</li>
 * <li>a request without the {@code params} its method requires ({@code "params": null}) is refused
 * with "invalid params", as is one whose parameters lack a field the protocol requires;</li>
 * <li>anything else goes on to the server.</li>
 * </ul>
 */
final class GuardedMessageProducer implements MessageProducer, Closeable {
	/** The longest message content read: a model document of tens of MB fits; more is skipped unread. */
	static final int MAX_CONTENT_BYTES = 64 << 20;
	/** The deepest nesting of arrays and objects read; the protocol's own messages nest fewer than 20 levels. */
	static final int MAX_DEPTH = 100;
	/** The longest header line read. */
	static final int MAX_HEADER_LINE = 8 << 10;
	/** How much of a message's start is kept (to find its id) when the whole is too long to read. */
	private static final int PREFIX_BYTES = 64 << 10;

	private static final Logger LOG = Logger.getLogger(GuardedMessageProducer.class.getName());
	private static final String CONTENT_LENGTH = "content-length";
	/** A method name as the protocol writes them: only such a name is quoted in the log. */
	private static final java.util.regex.Pattern METHOD_NAME = java.util.regex.Pattern.compile("[A-Za-z$][A-Za-z0-9/$_.-]{0,79}");

	private final InputStream input;
	private final MessageJsonHandler json;
	private final MessageIssueHandler issues;
	private volatile boolean running;

	GuardedMessageProducer(InputStream input, MessageJsonHandler json, MessageIssueHandler issues) {
		this.input = input;
		this.json = json;
		this.issues = issues;
	}

	@Override
	public void listen(MessageConsumer callback) {
		running = true;
		MessageConsumer validated = new ReflectiveMessageValidator(callback);
		try {
			while (running) {
				Frame frame = readFrame();
				if (frame == null) {
					return;
				}
				if (frame.error != null) {
					refuse(frame.content, ResponseErrorCode.InvalidRequest, frame.error);
					continue;
				}
				deliver(frame.content, frame.charset, validated);
			}
		} catch (InterruptedIOException | ClosedChannelException e) {
			// the connection was closed under us: the end of listening
		} catch (IOException e) {
			throw new JsonRpcException(e);
		}
	}

	@Override
	public void close() {
		running = false;
	}

	private record Frame(byte[] content, Charset charset, String error) {
	}

	/** The next message's content, whole, or null at the end of the stream. */
	private Frame readFrame() throws IOException {
		while (true) {
			Frame frame = readOneFrame();
			if (frame == null || frame.content != null) {
				return frame;
			}
		}
	}

	/** The next message's content, or a frame without content when it had no length to read it by. */
	private Frame readOneFrame() throws IOException {
		long length = -1;
		Charset charset = StandardCharsets.UTF_8;
		String lengthProblem = null;
		while (true) {
			String line = readHeaderLine();
			if (line == null) {
				return null;
			}
			if (line.isEmpty()) {
				if (length >= 0 || lengthProblem != null) {
					break;
				}
				continue; // blank lines between messages: nothing to read yet
			}
			int colon = line.indexOf(':');
			if (colon < 0) {
				lengthProblem = lengthProblem != null ? lengthProblem : "a header line without ':'";
				continue;
			}
			String name = line.substring(0, colon).trim().toLowerCase(Locale.ROOT);
			String value = line.substring(colon + 1).trim();
			if (name.equals(CONTENT_LENGTH)) {
				try {
					length = Long.parseLong(value);
					if (length < 0) {
						throw new NumberFormatException();
					}
				} catch (NumberFormatException e) {
					lengthProblem = "Content-Length '" + abbreviate(value) + "' is not a length";
				}
			} else if (name.equals("content-type")) {
				int at = value.indexOf("charset=");
				if (at >= 0) {
					try {
						charset = Charset.forName(value.substring(at + 8).trim().replace("\"", ""));
					} catch (RuntimeException e) {
						lengthProblem = "unknown charset in '" + abbreviate(value) + "'";
					}
				}
			}
		}
		if (length < 0) {
			// without a length the content cannot be told from the next message's headers: it is read as headers
			LOG.info("ignored a message without a readable Content-Length header");
			return new Frame(null, charset, null);
		}
		if (length > MAX_CONTENT_BYTES) {
			byte[] prefix = input.readNBytes(PREFIX_BYTES);
			skipFully(length - prefix.length);
			return new Frame(prefix, charset, "the message has " + length + " bytes; the Triad language server reads at most "
					+ MAX_CONTENT_BYTES + " bytes per message");
		}
		byte[] content = input.readNBytes((int) length);
		if (content.length < length) {
			return null;
		}
		if (lengthProblem != null) {
			return new Frame(content, charset, lengthProblem);
		}
		return new Frame(content, charset, null);
	}

	/** One header line without its line end, at most {@link #MAX_HEADER_LINE} characters kept; null at the end of the stream. */
	private String readHeaderLine() throws IOException {
		StringBuilder line = new StringBuilder();
		while (true) {
			int c = input.read();
			if (c < 0) {
				return null;
			}
			if (c == '\n') {
				return line.toString();
			}
			if (c != '\r' && line.length() < MAX_HEADER_LINE) {
				line.append((char) c);
			}
		}
	}

	private void skipFully(long n) throws IOException {
		byte[] sink = new byte[1 << 16];
		while (n > 0) {
			int read = input.read(sink, 0, (int) Math.min(sink.length, n));
			if (read < 0) {
				return;
			}
			n -= read;
		}
	}

	private void deliver(byte[] content, Charset charset, MessageConsumer validated) {
		int depth = depthBeyond(content, MAX_DEPTH);
		if (depth > MAX_DEPTH) {
			refuse(content, ResponseErrorCode.InvalidRequest,
					"the message nests arrays and objects more than " + MAX_DEPTH + " levels deep, more than the Triad language server reads");
			return;
		}
		Message message;
		try {
			message = json.parseMessage(new String(content, charset));
		} catch (MessageIssueException e) {
			reject(e.getRpcMessage(), e.getIssues());
			return;
		} catch (RuntimeException | StackOverflowError e) {
			refuse(content, ResponseErrorCode.ParseError, "the message is not a JSON-RPC message: " + reason(e));
			return;
		}
		if (message == null) {
			refuse(content, ResponseErrorCode.ParseError, "the message is empty");
			return;
		}
		String missing = missingParams(message);
		if (missing != null) {
			reject(message, List.of(new MessageIssue(missing, ResponseErrorCode.InvalidParams.getValue())));
			return;
		}
		try {
			validated.consume(message);
		} catch (MessageIssueException e) {
			reject(e.getRpcMessage(), e.getIssues());
		}
	}

	/**
	 * A request is answered with the first issue; anything else (a notification, a response) has nobody to
	 * answer and is one line in the log, where LSP4J would log a warning with a stack trace.
	 */
	private void reject(Message message, List<MessageIssue> found) {
		if (message instanceof RequestMessage) {
			// the cause's words, not the cause: LSP4J would send the exception itself (class names, trace) as the error's data
			issues.handle(message, found.stream().map(i -> new MessageIssue(
					i.getCause() == null ? i.getText() : i.getText() + " " + reason(i.getCause()), i.getIssueCode())).toList());
			return;
		}
		String method = message instanceof NotificationMessage n ? n.getMethod() : null;
		String what = method != null && METHOD_NAME.matcher(method).matches() ? "notification '" + method + "'" : "message";
		LOG.info("ignored a " + what + " the server cannot read (" + (found.isEmpty() ? "" : found.get(0).getIssueCode()) + ")");
	}

	/** Why a request or notification of a known method lacks the parameters its method takes, or null. */
	private String missingParams(Message message) {
		String method;
		Object params;
		if (message instanceof RequestMessage r) {
			method = r.getMethod();
			params = r.getParams();
		} else if (message instanceof NotificationMessage n) {
			method = n.getMethod();
			params = n.getParams();
		} else {
			return null;
		}
		if (params != null || method == null) {
			return null;
		}
		JsonRpcMethod known = json.getJsonRpcMethod(method);
		if (known == null || known.getParameterTypes().length == 0 || method.equals("initialized")) {
			return null;
		}
		return "'" + method + "' needs params, and the message has none";
	}

	/**
	 * Answers a message the server does not read: an error answer to its request when its id can be read
	 * off its text; otherwise (a notification, or no id to answer to) one logged line.
	 */
	private void refuse(byte[] content, ResponseErrorCode code, String why) {
		RequestMessage request = leniently(content);
		if (request == null) {
			// the log line names the code only: the reason quotes the client's text, which has no place in a log
			LOG.info("ignored a message that has no id to answer to (" + code + ")");
			return;
		}
		issues.handle(request, List.of(new MessageIssue(why, code.getValue())));
	}

	/**
	 * The request the content starts as, from its top-level {@code id} and {@code method} alone; Gson's
	 * reader skips values without recursion, so this reads even a message too deep to parse.
	 */
	static RequestMessage leniently(byte[] content) {
		RequestMessage request = new RequestMessage();
		boolean hasId = false;
		try (JsonReader reader = new JsonReader(new StringReader(new String(content, StandardCharsets.UTF_8)))) {
			reader.beginObject();
			while (reader.hasNext()) {
				String name = reader.nextName();
				if (name.equals("id") && reader.peek() == JsonToken.NUMBER) {
					String number = reader.nextString();
					try {
						request.setId(Integer.parseInt(number));
					} catch (NumberFormatException e) {
						request.setId(number);
					}
					hasId = true;
				} else if (name.equals("id") && reader.peek() == JsonToken.STRING) {
					request.setId(reader.nextString());
					hasId = true;
				} else if (name.equals("method") && reader.peek() == JsonToken.STRING) {
					request.setMethod(reader.nextString());
				} else {
					reader.skipValue();
				}
			}
		} catch (IOException | RuntimeException | StackOverflowError e) {
			// what was read so far is all there is to answer to
		}
		if (!hasId) {
			return null;
		}
		if (request.getMethod() == null) {
			request.setMethod("");
		}
		return request;
	}

	/** The depth of the deepest nesting of arrays and objects in the JSON text, counted up to {@code limit + 1}. */
	static int depthBeyond(byte[] content, int limit) {
		int depth = 0;
		int deepest = 0;
		boolean inString = false;
		for (int i = 0; i < content.length; i++) {
			byte b = content[i];
			if (inString) {
				if (b == '\\') {
					i++;
				} else if (b == '"') {
					inString = false;
				}
			} else if (b == '"') {
				inString = true;
			} else if (b == '[' || b == '{') {
				depth++;
				if (depth > deepest) {
					deepest = depth;
					if (deepest > limit) {
						return deepest;
					}
				}
			} else if (b == ']' || b == '}') {
				depth--;
			}
		}
		return deepest;
	}

	/** What went wrong, in the words of its innermost cause, on one line (no exception class names). */
	private static String reason(Throwable e) {
		if (e instanceof StackOverflowError) {
			return "it nests too deep to read";
		}
		Throwable t = e;
		while (t.getCause() != null && t.getCause() != t) {
			t = t.getCause();
		}
		String message = t.getMessage() == null ? "unreadable" : t.getMessage();
		int end = message.indexOf('\n');
		return end < 0 ? message : message.substring(0, end);
	}

	private static String abbreviate(String s) {
		return s.length() <= 40 ? s : s.substring(0, 40) + "...";
	}
}
