package org.triad.fuzz;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.net.URI;
import java.net.URLEncoder;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import com.code_intelligence.jazzer.api.FuzzedDataProvider;
import com.code_intelligence.jazzer.junit.FuzzTest;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.triad.service.AccessTokens;
import org.triad.service.TriadService;

/**
 * The service's HTTP API, driven by its own OpenAPI document: the input picks an operation of
 * {@code /api/openapi.json}, fills its path parameters, picks a token (staff, operator or a wrong one) and
 * supplies the body. Every answer is below 500, and every error is JSON {@code {"error", "message"}}
 * (never a stack trace, never an exception's text). One service (dry-run robots, a temporary database)
 * serves the whole run.
 */
class HttpApiFuzzTest {
	private static final String STAFF = "staff-token-for-fuzzing";
	private static final String OPERATOR = "operator-token-for-fuzzing";
	private static final ObjectMapper JSON = new ObjectMapper();
	private static final Pattern PARAMETER = Pattern.compile("\\{[^}]+}");

	/** Started on first use, stopped when the JVM ends. */
	private static final class Running {
		static final HttpClient HTTP = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(10)).build();
		static final TriadService SERVICE = start();
		static final List<String[]> OPERATIONS = operations();

		private static TriadService start() {
			try {
				Path dir = Files.createTempDirectory("triad-http-fuzz");
				TriadService s = TriadService.start(new TriadService.Options(Path.of("../models/hospital/src/main/models").toAbsolutePath().normalize(),
						List.of("dry:2"), null, dir.resolve("db"), null, "127.0.0.1", 0,
						Map.of(AccessTokens.SUBMIT_ENV, STAFF, AccessTokens.OPERATOR_ENV, OPERATOR)));
				Runtime.getRuntime().addShutdownHook(new Thread(s::close, "http-fuzz-service"));
				return s;
			} catch (IOException e) {
				throw new java.io.UncheckedIOException(e);
			}
		}

		private static List<String[]> operations() {
			try {
				HttpResponse<String> r = HTTP.send(HttpRequest.newBuilder(URI.create(SERVICE.url() + "/api/openapi.json")).build(),
						HttpResponse.BodyHandlers.ofString());
				List<String[]> ops = new ArrayList<>();
				for (Iterator<Map.Entry<String, JsonNode>> paths = JSON.readTree(r.body()).get("paths").fields(); paths.hasNext();) {
					Map.Entry<String, JsonNode> p = paths.next();
					for (Iterator<String> methods = p.getValue().fieldNames(); methods.hasNext();) {
						String m = methods.next();
						if (List.of("get", "post", "put", "delete", "patch").contains(m)) {
							ops.add(new String[] { m.toUpperCase(java.util.Locale.ROOT), p.getKey() });
						}
					}
				}
				return ops;
			} catch (IOException e) {
				throw new java.io.UncheckedIOException(e);
			} catch (InterruptedException e) {
				Thread.currentThread().interrupt();
				throw new IllegalStateException(e);
			}
		}
	}

	@FuzzTest(maxDuration = "10m")
	void api(FuzzedDataProvider data) throws Exception {
		String[] op = Running.OPERATIONS.get(data.consumeInt(0, Running.OPERATIONS.size() - 1));
		String token = switch (data.consumeInt(0, 2)) {
			case 0 -> STAFF;
			case 1 -> OPERATOR;
			default -> "wrong." + data.consumeString(20);
		};
		Matcher m = PARAMETER.matcher(op[1]);
		StringBuilder path = new StringBuilder();
		while (m.find()) {
			m.appendReplacement(path, Matcher.quoteReplacement(URLEncoder.encode(data.consumeString(40), StandardCharsets.UTF_8).replace("+", "%20")));
		}
		m.appendTail(path);
		String query = data.consumeBoolean() ? "?state=" + URLEncoder.encode(data.consumeString(20), StandardCharsets.UTF_8) : "";
		byte[] body = data.consumeRemainingAsBytes();
		String target = path + query;
		if (target.contains("%2F") || target.contains("%5C")) {
			target = target.replace("%2F", "_").replace("%5C", "_"); // an encoded slash is another path, not this operation's
		}
		HttpRequest.Builder b = HttpRequest.newBuilder(URI.create(Running.SERVICE.url() + target)).timeout(Duration.ofSeconds(30))
				.header("Authorization", "Bearer " + token);
		if (op[0].equals("GET")) {
			b.GET();
		} else {
			b.header("Content-Type", "application/json").method(op[0], HttpRequest.BodyPublishers.ofByteArray(body));
		}
		HttpResponse<String> r = Running.HTTP.send(b.build(), HttpResponse.BodyHandlers.ofString());
		assertTrue(r.statusCode() < 500 || r.statusCode() == 503 && r.body().contains("\"too-many-streams\""),
				op[0] + " " + target + " answered " + r.statusCode() + ": " + r.body());
		if (r.statusCode() >= 400) {
			JsonNode error;
			try {
				error = JSON.readTree(r.body());
			} catch (IOException e) {
				fail(op[0] + " " + target + " answered " + r.statusCode() + " without a JSON error: " + r.body());
				return;
			}
			assertTrue(error != null && error.hasNonNull("error") && error.hasNonNull("message"),
					op[0] + " " + target + " answered " + r.statusCode() + " without error and message: " + r.body());
		}
	}
}
