package org.triad.dsl.ide;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Stream;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.dsl.ide.server.TriadLanguageServer;
import org.triad.dsl.ide.server.TriadLanguageServerMain;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * The language server as {@code triad lsp} runs it, in its own JVM, spoken to byte by byte over its
 * standard input and output the way an attacker or a broken client would: every message gets an
 * answer or a proper error, the stream stays in step, and nothing is printed as a failure.
 */
class LanguageServerStreamTest {
	private static final long TIMEOUT_S = 120;

	@TempDir
	static Path workspace;

	private static Process server;
	private static OutputStream toServer;
	private static final Map<Integer, JsonObject> answers = new ConcurrentHashMap<>();
	private static final ByteArrayOutputStream stderr = new ByteArrayOutputStream();
	private static final AtomicInteger ids = new AtomicInteger(100);

	@BeforeAll
	static void startServer() throws Exception {
		try (Stream<Path> files = Files.list(Path.of("src", "test", "resources", "rules", "_base"))) {
			for (Path f : files.toList()) {
				Files.copy(f, workspace.resolve(f.getFileName()));
			}
		}
		String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
		server = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"), TriadLanguageServerMain.class.getName())
				.directory(workspace.toFile()).start();
		toServer = server.getOutputStream();
		Thread reader = new Thread(() -> readAnswers(server.getInputStream()), "lsp-answers");
		reader.setDaemon(true);
		reader.start();
		Thread errors = new Thread(() -> {
			try {
				server.getErrorStream().transferTo(stderr);
			} catch (IOException e) {
				// the server ended
			}
		}, "lsp-stderr");
		errors.setDaemon(true);
		errors.start();
		JsonObject init = request("initialize", "{\"processId\":null,\"rootUri\":\"" + uri(workspace) + "\",\"capabilities\":{}}");
		assertTrue(init.has("result"), init::toString);
		send("{\"jsonrpc\":\"2.0\",\"method\":\"initialized\",\"params\":{}}");
	}

	@AfterAll
	static void stopServer() throws Exception {
		if (server == null) {
			return;
		}
		try {
			request("shutdown", "null");
			send("{\"jsonrpc\":\"2.0\",\"method\":\"exit\"}");
			server.waitFor(30, TimeUnit.SECONDS);
		} finally {
			server.destroyForcibly();
		}
	}

	@Test
	void aMessageNested100000DeepIsRefusedAndTheNextRequestAnswered() throws Exception {
		int id = ids.incrementAndGet();
		String deep = "[".repeat(100_000) + "]".repeat(100_000);
		send("{\"jsonrpc\":\"2.0\",\"id\":" + id + ",\"method\":\"textDocument/hover\",\"params\":" + deep + "}");
		JsonObject refused = answer(id);
		assertEquals(-32600, error(refused).get("code").getAsInt(), refused::toString);
		assertTrue(error(refused).get("message").getAsString().contains("100 levels"), refused::toString);

		send("[".repeat(100_000)); // nothing to answer to: no id, not even complete
		assertAnswersNextRequest();
		assertNoFailurePrinted();
	}

	@Test
	void malformedJsonIsAParseErrorAndTheStreamStaysInStep() throws Exception {
		int id = ids.incrementAndGet();
		send("{\"jsonrpc\":\"2.0\",\"id\":" + id + ",\"method\":\"textDocument/hover\", garbage, \"params\": {} }");
		JsonObject refused = answer(id);
		assertEquals(-32700, error(refused).get("code").getAsInt(), refused::toString);
		assertAnswersNextRequest();
		assertNoFailurePrinted();
	}

	@Test
	void hoverWithNullParamsIsInvalidParamsAndPrintsNothing() throws Exception {
		JsonObject refused = request("textDocument/hover", "null");
		assertEquals(-32602, error(refused).get("code").getAsInt(), refused::toString);
		JsonObject withoutDocument = request("textDocument/hover", "{\"position\":{\"line\":0,\"character\":0}}");
		assertEquals(-32602, error(withoutDocument).get("code").getAsInt(), withoutDocument::toString);
		assertAnswersNextRequest();
		assertNoFailurePrinted();
	}

	@Test
	void formattingADocumentOverTheBoundIsRefusedAtOnce() throws Exception {
		Path big = workspace.resolve("Big.cd");
		// one long comment: large for the formatter, yet quick to parse, so the test does not wait for a long check
		String text = "classdiagram Big {\n  class Box;\n}\n/*" + "x".repeat(TriadLanguageServer.MAX_FORMATTED_CHARS) + "*/\n";
		Files.writeString(big, text);
		send("{\"jsonrpc\":\"2.0\",\"method\":\"textDocument/didOpen\",\"params\":{\"textDocument\":{\"uri\":\"" + uri(big)
				+ "\",\"languageId\":\"triad-cd\",\"version\":1,\"text\":\"" + text.replace("\n", "\\n") + "\"}}}");
		JsonObject refused = request("textDocument/formatting",
				"{\"textDocument\":{\"uri\":\"" + uri(big) + "\"},\"options\":{\"tabSize\":2,\"insertSpaces\":true}}");
		assertEquals(-32803, error(refused).get("code").getAsInt(), refused::toString);
		assertTrue(error(refused).get("message").getAsString().contains("at most " + TriadLanguageServer.MAX_FORMATTED_CHARS), refused::toString);
		assertAnswersNextRequest();
		assertNoFailurePrinted();
	}

	private static void assertAnswersNextRequest() throws Exception {
		JsonObject symbols = request("workspace/symbol", "{\"query\":\"boxAt\"}");
		assertTrue(symbols.has("result"), symbols::toString);
		assertTrue(symbols.get("result").toString().contains("boxAt"), symbols::toString);
	}

	private static void assertNoFailurePrinted() {
		String printed = stderr.toString(StandardCharsets.UTF_8);
		assertFalse(printed.contains("SEVERE") || printed.contains("Exception") || printed.contains("\tat "), printed);
	}

	private static JsonObject error(JsonObject answer) {
		assertTrue(answer.has("error"), answer::toString);
		return answer.getAsJsonObject("error");
	}

	private static JsonObject request(String method, String params) throws Exception {
		int id = ids.incrementAndGet();
		send("{\"jsonrpc\":\"2.0\",\"id\":" + id + ",\"method\":\"" + method + "\",\"params\":" + params + "}");
		return answer(id);
	}

	private static JsonObject answer(int id) throws InterruptedException {
		long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(TIMEOUT_S);
		synchronized (answers) {
			while (!answers.containsKey(id) && System.nanoTime() < end && server.isAlive()) {
				answers.wait(200);
			}
		}
		JsonObject answer = answers.get(id);
		assertNotNull(answer, () -> "no answer to request " + id + "; the server printed: " + stderr.toString(StandardCharsets.UTF_8));
		return answer;
	}

	private static synchronized void send(String content) throws IOException {
		byte[] bytes = content.getBytes(StandardCharsets.UTF_8);
		toServer.write(("Content-Length: " + bytes.length + "\r\n\r\n").getBytes(StandardCharsets.US_ASCII));
		toServer.write(bytes);
		toServer.flush();
	}

	/** Reads the server's messages by their Content-Length and keeps the answers by id. */
	private static void readAnswers(InputStream in) {
		try {
			while (true) {
				int length = -1;
				StringBuilder line = new StringBuilder();
				while (true) {
					int c = in.read();
					if (c < 0) {
						return;
					}
					if (c == '\n') {
						String header = line.toString().trim();
						line.setLength(0);
						if (header.isEmpty()) {
							break;
						}
						if (header.toLowerCase().startsWith("content-length:")) {
							length = Integer.parseInt(header.substring(15).trim());
						}
					} else {
						line.append((char) c);
					}
				}
				JsonElement message = JsonParser.parseString(new String(in.readNBytes(length), StandardCharsets.UTF_8));
				JsonObject o = message.getAsJsonObject();
				if (o.has("id") && !o.get("id").isJsonNull() && !o.has("method")) {
					synchronized (answers) {
						answers.put(o.get("id").getAsInt(), o);
						answers.notifyAll();
					}
				}
			}
		} catch (IOException | RuntimeException e) {
			// the server ended; the waiting test reports the missing answer
		}
	}

	private static String uri(Path p) {
		return p.toUri().toString().replaceFirst("^file:/(?!/)", "file:///");
	}
}
