package org.triad.dsl.ide.server;

import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Future;

import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.jsonrpc.MessageConsumer;
import org.eclipse.lsp4j.jsonrpc.MessageProducer;
import org.eclipse.lsp4j.jsonrpc.RemoteEndpoint;
import org.eclipse.lsp4j.jsonrpc.json.ConcurrentMessageProcessor;
import org.eclipse.lsp4j.jsonrpc.json.MessageJsonHandler;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.xtext.ide.server.LanguageServerImpl;
import org.eclipse.xtext.ide.server.LaunchArgs;
import org.eclipse.xtext.ide.server.ServerLauncher;

import com.google.inject.Inject;

/**
 * Starts the language server on standard input and output ({@code triad lsp}) with
 * {@link ProtocolErrors} answering failed requests, the {@link GuardedMessageProducer} reading the
 * client's messages, and the {@link GuardedServerModule}.
 */
public class TriadServerLauncher extends ServerLauncher {
	@Inject
	private LanguageServerImpl languageServer;

	public static void main(String[] args) {
		launch(TriadServerLauncher.class.getName(), args, new TriadServerModule());
	}

	/** The server's end of a connection, as {@code triad lsp} and the tests make it. */
	public static Launcher<LanguageClient> createLauncher(LanguageServerImpl server, InputStream in, OutputStream out, boolean validate,
			PrintWriter trace) {
		Launcher<LanguageClient> launcher = new GuardedBuilder().setLocalService(server)
				.setRemoteInterface(LanguageClient.class).setInput(in).setOutput(out).validateMessages(validate).traceMessages(trace)
				.setExceptionHandler(ProtocolErrors::toResponseError).create();
		server.connect(launcher.getRemoteProxy());
		return launcher;
	}

	/** LSP4J's launcher reading the client's messages with the {@link GuardedMessageProducer}. */
	private static final class GuardedBuilder extends Launcher.Builder<LanguageClient> {
		private MessageJsonHandler json;
		private RemoteEndpoint endpoint;

		@Override
		protected RemoteEndpoint createRemoteEndpoint(MessageJsonHandler jsonHandler) {
			json = jsonHandler;
			endpoint = super.createRemoteEndpoint(jsonHandler);
			return endpoint;
		}

		@Override
		protected ConcurrentMessageProcessor createMessageProcessor(MessageProducer reader, MessageConsumer consumer, LanguageClient proxy) {
			return super.createMessageProcessor(new GuardedMessageProducer(input, json, endpoint), consumer, proxy);
		}
	}

	@Override
	public void start(LaunchArgs args) {
		Future<Void> listening = createLauncher(languageServer, args.getIn(), args.getOut(), args.isValidate(), args.getTrace()).startListening();
		try {
			listening.get();
		} catch (InterruptedException e) {
			Thread.currentThread().interrupt();
		} catch (ExecutionException e) {
			throw new IllegalStateException("the language server's connection failed", e.getCause());
		}
	}
}
