package org.triad.service;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.Iterator;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.StreamReadConstraints;
import com.fasterxml.jackson.core.exc.StreamConstraintsException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import io.javalin.http.Context;

/**
 * The limits on what a client may send, enforced while reading (a body is never read whole before it is
 * judged, chunked or not), each refused with a 4xx whose message names the limit:
 * <ul>
 * <li>a body of at most {@value #MAX_BODY} bytes (413 {@code too-large});</li>
 * <li>JSON nested at most {@value #MAX_DEPTH} deep, numbers of at most {@value #MAX_NUMBER_LENGTH} characters,
 * strings and names of at most {@value #MAX_STRING} characters (400 {@code limit-exceeded}).</li>
 * </ul>
 */
final class RequestLimits {
    /** Largest request body accepted, bytes: a submission is a few hundred. */
    static final int MAX_BODY = 64 * 1024;
    static final int MAX_DEPTH = 32;
    static final int MAX_NUMBER_LENGTH = 40;
    static final int MAX_STRING = 1000;

    private RequestLimits() {
    }

    /** A mapper whose parser stops at the limits as it reads. */
    static ObjectMapper mapper() {
        // Jackson's string limit also counts a number's digits while it reads them: it stays above the body limit, and
        // checkStrings holds strings to MAX_STRING exactly
        return new ObjectMapper(JsonFactory.builder().streamReadConstraints(StreamReadConstraints.builder().maxNestingDepth(MAX_DEPTH)
                .maxNumberLength(MAX_NUMBER_LENGTH).maxStringLength(2 * MAX_BODY).build()).build());
    }

    /**
     * Reads the request's body, at most {@value #MAX_BODY} bytes: one byte more and the request is refused
     * there, with the connection closed after the answer (the rest is never read).
     */
    static byte[] read(Context ctx) {
        long declared = ctx.contentLength();
        if (declared > MAX_BODY) {
            throw tooLarge(ctx, "the body has " + declared + " bytes; at most " + MAX_BODY + " are accepted (the body limit)");
        }
        try (InputStream in = ctx.req().getInputStream()) {
            byte[] body = in.readNBytes(MAX_BODY + 1);
            if (body.length > MAX_BODY) {
                throw tooLarge(ctx, "the body is larger than " + MAX_BODY + " bytes (the body limit); refused after reading " + body.length);
            }
            return body;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read the request body: " + e.getMessage(), e);
        }
    }

    private static ServiceError tooLarge(Context ctx, String message) {
        ctx.header("Connection", "close");
        return new ServiceError(413, "too-large", message);
    }

    /** Parses a JSON body within the limits; a 400 naming what is wrong, or the limit, otherwise. */
    static JsonNode parse(ObjectMapper json, byte[] body) {
        String text = new String(body, StandardCharsets.UTF_8);
        JsonNode n;
        try {
            n = json.readTree(text);
        } catch (StreamConstraintsException e) {
            throw new ServiceError(400, "limit-exceeded", limitOf(e));
        } catch (JsonProcessingException e) {
            String where = e.getLocation() == null ? "" : " at line " + e.getLocation().getLineNr() + ", column " + e.getLocation().getColumnNr();
            throw new ServiceError(400, "malformed-json", "the body is not JSON: " + e.getOriginalMessage() + where);
        }
        if (n == null || n.isMissingNode()) {
            throw new ServiceError(400, "malformed-json", "the body is empty; expected a JSON object");
        }
        checkStrings(n);
        return n;
    }

    private static String limitOf(StreamConstraintsException e) {
        String m = String.valueOf(e.getMessage());
        if (m.contains("nesting depth")) {
            return "the body nests JSON deeper than " + MAX_DEPTH + " levels (the depth limit)";
        }
        if (m.contains("Number value length") || m.contains("Number")) {
            return "a number in the body is longer than " + MAX_NUMBER_LENGTH + " characters (the number limit)";
        }
        if (m.contains("String value length") || m.contains("Name length")) {
            return "a string in the body is longer than " + MAX_STRING + " characters (the string limit)";
        }
        return "the body exceeds a limit: " + m.lines().findFirst().orElse(m);
    }

    /** Jackson checks string lengths in steps of its buffers; this makes the limit exact. */
    private static void checkStrings(JsonNode n) {
        if (n.isTextual() && n.textValue().length() > MAX_STRING) {
            throw new ServiceError(400, "limit-exceeded", "a string in the body is longer than " + MAX_STRING + " characters (the string limit)");
        }
        for (Iterator<java.util.Map.Entry<String, JsonNode>> it = n.fields(); it.hasNext();) {
            java.util.Map.Entry<String, JsonNode> f = it.next();
            if (f.getKey().length() > MAX_STRING) {
                throw new ServiceError(400, "limit-exceeded", "a name in the body is longer than " + MAX_STRING + " characters (the string limit)");
            }
            checkStrings(f.getValue());
        }
        if (n.isArray()) {
            n.forEach(RequestLimits::checkStrings);
        }
    }
}
