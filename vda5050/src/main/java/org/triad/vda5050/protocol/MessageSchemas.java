package org.triad.vda5050.protocol;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.EnumMap;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;

import com.fasterxml.jackson.databind.JsonNode;
import com.networknt.schema.JsonSchema;
import com.networknt.schema.JsonSchemaFactory;
import com.networknt.schema.SpecVersion;
import com.networknt.schema.ValidationMessage;

/**
 * The official VDA 5050 2.1.0 JSON schemas (copied unchanged into {@code src/main/resources/vda5050/schemas},
 * see the ORIGIN file there) and validation of a message against the schema of its topic.
 */
public final class MessageSchemas {
    private static final MessageSchemas INSTANCE = new MessageSchemas();

    private final Map<Topic, JsonSchema> schemas = new EnumMap<>(Topic.class);

    private MessageSchemas() {
        JsonSchemaFactory factory = JsonSchemaFactory.getInstance(SpecVersion.VersionFlag.V202012);
        for (Topic t : Topic.values()) {
            String resource = "/vda5050/schemas/" + t.leaf() + ".schema";
            try (InputStream in = MessageSchemas.class.getResourceAsStream(resource)) {
                if (in == null) {
                    throw new IllegalStateException("the VDA 5050 schema " + resource + " is missing from the class path");
                }
                schemas.put(t, factory.getSchema(VdaJson.mapper().readTree(in)));
            } catch (IOException e) {
                throw new UncheckedIOException("cannot read the VDA 5050 schema " + resource, e);
            }
        }
    }

    public static MessageSchemas get() {
        return INSTANCE;
    }

    /** The violations of the topic's schema, as {@code $.path: message} lines; empty when the message conforms. */
    public Set<String> violations(Topic topic, JsonNode message) {
        Set<ValidationMessage> found = schemas.get(topic).validate(message);
        return found.stream().map(ValidationMessage::getMessage).collect(Collectors.toCollection(java.util.TreeSet::new));
    }

    /** Throws {@link VdaMessageException} naming the first violations if the message does not conform. */
    public void check(Topic topic, JsonNode message) {
        Set<String> v = violations(topic, message);
        if (!v.isEmpty()) {
            throw new VdaMessageException("violates the " + topic.leaf() + " schema: " + v.stream().limit(3).collect(Collectors.joining("; "))
                    + (v.size() > 3 ? " (and " + (v.size() - 3) + " more)" : ""));
        }
    }
}
