package org.triad.vda5050.protocol;

import java.io.IOException;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/** Reading and writing VDA 5050 messages as JSON (unknown fields are allowed: the schemas allow vendor extensions). */
public final class VdaJson {
    private static final ObjectMapper MAPPER = new ObjectMapper()
            .configure(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES, false);

    private VdaJson() {
    }

    public static ObjectMapper mapper() {
        return MAPPER;
    }

    public static byte[] write(Object message) {
        try {
            return MAPPER.writeValueAsBytes(message);
        } catch (JsonProcessingException e) {
            throw new IllegalArgumentException("cannot write " + message.getClass().getSimpleName() + " as JSON: " + e.getOriginalMessage(), e);
        }
    }

    public static JsonNode tree(Object message) {
        return MAPPER.valueToTree(message);
    }

    /** Parses a payload; throws {@link VdaMessageException} with a one-line reason if it is not JSON. */
    public static JsonNode parse(byte[] payload) {
        try {
            JsonNode n = MAPPER.readTree(payload);
            if (n == null || n.isMissingNode()) {
                throw new VdaMessageException("empty payload");
            }
            return n;
        } catch (JsonProcessingException e) {
            throw new VdaMessageException("not valid JSON: " + e.getOriginalMessage().replace('\n', ' '));
        } catch (IOException e) {
            throw new VdaMessageException("unreadable payload: " + e.getMessage());
        }
    }

    /** Binds an already validated message to its record type. */
    public static <T> T bind(JsonNode tree, Class<T> type) {
        try {
            return MAPPER.treeToValue(tree, type);
        } catch (JsonProcessingException e) {
            throw new VdaMessageException("cannot read as " + type.getSimpleName() + ": " + e.getOriginalMessage().replace('\n', ' '));
        }
    }
}
