package org.triad.service;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.triad.runtime.app.DomainObject;
import org.triad.runtime.app.EnumValue;
import org.triad.runtime.schema.AppSchema;
import org.triad.runtime.schema.Param;
import org.triad.runtime.schema.TaskSchema;
import org.triad.runtime.schema.TypeSchema;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * The tasks people may submit, read from the task models, with the objects the world lists: checks a
 * submission {@code {"task": "Fetch", "args": {"i": "gauze", ...}}} against the task's parameter types
 * and the objects that exist, field by field.
 */
public final class TaskCatalog {
    public static final int MIN_PRIORITY = -100;
    public static final int MAX_PRIORITY = 100;

    private final AppSchema schema;
    private final Map<String, DomainObject> objects;

    public TaskCatalog(AppSchema schema, Map<String, DomainObject> objects) {
        this.schema = schema;
        this.objects = new LinkedHashMap<>(objects);
    }

    public AppSchema schema() {
        return schema;
    }

    /** A checked submission: the task, its arguments as submitted (JSON) and as runtime values, in parameter order. */
    /** {@code priority}: higher is dispatched first; {@value #MIN_PRIORITY} to {@value #MAX_PRIORITY}, 0 unless given. */
    public record TaskCall(String task, ObjectNode args, List<Object> values, int priority) {
        public String describe() {
            StringBuilder b = new StringBuilder(task).append('(');
            for (int i = 0; i < values.size(); i++) {
                b.append(i > 0 ? ", " : "").append(values.get(i));
            }
            return b.append(')').toString();
        }
    }

    /** One wrong field of a submission: {@code field} is a JSON path such as {@code args.i}. */
    public record FieldError(String field, String message) {
    }

    /** A submission that does not fit the task models; HTTP 422 (400 when the body is not a JSON object). */
    public static final class InvalidSubmission extends ServiceError {
        private static final long serialVersionUID = 1L;
        private final transient List<FieldError> errors;

        InvalidSubmission(int status, String code, List<FieldError> errors) {
            super(status, code, errors.stream().map(e -> e.field() + ": " + e.message()).reduce((a, b) -> a + "; " + b).orElse(code));
            this.errors = List.copyOf(errors);
        }

        public List<FieldError> errors() {
            return errors;
        }
    }

    /** The names of the objects of {@code type} or a subtype, in the world's order. */
    public List<String> objectsOf(String type) {
        List<String> names = new ArrayList<>();
        for (DomainObject o : objects.values()) {
            if (schema.isSubtype(o.typeName(), type)) {
                names.add(o.name());
            }
        }
        return names;
    }

    /** Checks a submission; every wrong field is reported at once. */
    public TaskCall check(JsonNode body) {
        if (body == null || !body.isObject()) {
            throw new InvalidSubmission(400, "malformed", List.of(new FieldError("", "the body must be a JSON object {\"task\": NAME, \"args\": {PARAM: VALUE, ...}}")));
        }
        List<FieldError> errors = new ArrayList<>();
        for (Iterator<String> it = body.fieldNames(); it.hasNext();) {
            String f = it.next();
            if (!f.equals("task") && !f.equals("args") && !f.equals("priority")) {
                errors.add(new FieldError(f, "unknown field; a submission has 'task', 'args' and optionally 'priority'"));
            }
        }
        int priority = 0;
        JsonNode priorityNode = body.get("priority");
        if (priorityNode != null && !priorityNode.isNull()) {
            if (priorityNode.isIntegralNumber() && priorityNode.canConvertToInt() && priorityNode.intValue() >= MIN_PRIORITY
                    && priorityNode.intValue() <= MAX_PRIORITY) {
                priority = priorityNode.intValue();
            } else {
                errors.add(new FieldError("priority", "a whole number from " + MIN_PRIORITY + " to " + MAX_PRIORITY + " (higher runs first), not " + priorityNode));
            }
        }
        JsonNode taskNode = body.get("task");
        if (taskNode == null || !taskNode.isTextual()) {
            errors.add(new FieldError("task", "required: the task's name, one of " + schema.tasks().keySet()));
            throw new InvalidSubmission(422, "invalid-task", errors);
        }
        TaskSchema task = schema.task(taskNode.asText()).orElse(null);
        if (task == null) {
            errors.add(new FieldError("task", "unknown task '" + taskNode.asText() + "'; the application has " + schema.tasks().keySet()));
            throw new InvalidSubmission(422, "unknown-task", errors);
        }
        JsonNode args = body.get("args");
        if (args == null || args.isNull()) {
            args = JsonNodeFactory.instance.objectNode();
        }
        if (!args.isObject()) {
            errors.add(new FieldError("args", "must be an object of the task's parameters " + signature(task)));
            throw new InvalidSubmission(422, "invalid-arguments", errors);
        }
        for (Iterator<String> it = args.fieldNames(); it.hasNext();) {
            String f = it.next();
            if (task.params().stream().noneMatch(p -> p.name().equals(f))) {
                errors.add(new FieldError("args." + f, "task " + task.name() + " has no parameter '" + f + "'; it takes " + signature(task)));
            }
        }
        List<Object> values = new ArrayList<>();
        ObjectNode canonical = JsonNodeFactory.instance.objectNode();
        for (Param p : task.params()) {
            JsonNode v = args.get(p.name());
            String field = "args." + p.name();
            if (v == null || v.isNull()) {
                errors.add(new FieldError(field, "missing: a " + p.type()));
                continue;
            }
            Object value = value(p, v, field, errors);
            if (value != null) {
                values.add(value);
                canonical.set(p.name(), v);
            }
        }
        if (!errors.isEmpty()) {
            throw new InvalidSubmission(422, "invalid-arguments", errors);
        }
        return new TaskCall(task.name(), canonical, values, priority);
    }

    private Object value(Param p, JsonNode v, String field, List<FieldError> errors) {
        switch (p.type()) {
            case "boolean":
                if (v.isBoolean()) {
                    return v.booleanValue();
                }
                break;
            case "int":
                if (v.isIntegralNumber() && v.canConvertToInt()) {
                    return v.intValue();
                }
                break;
            case "double":
                if (v.isNumber()) {
                    return v.doubleValue();
                }
                break;
            case "String":
                if (v.isTextual()) {
                    return v.textValue();
                }
                break;
            default:
                TypeSchema type = schema.types().get(p.type());
                if (type != null && type.isEnum()) {
                    String lit = v.isTextual() ? v.textValue().replaceFirst("^" + type.name() + "\\.", "") : null;
                    if (lit != null && type.literals().contains(lit)) {
                        return new EnumValue(type.name(), lit);
                    }
                    errors.add(new FieldError(field, "expected one of " + type.literals() + " (" + type.name() + "), got " + v));
                    return null;
                }
                if (!v.isTextual()) {
                    errors.add(new FieldError(field, "expected the name of a " + p.type() + ", got " + v));
                    return null;
                }
                DomainObject o = objects.get(v.textValue());
                if (o == null || !schema.isSubtype(o.typeName(), p.type())) {
                    errors.add(new FieldError(field, (o == null ? "no object '" + v.textValue() + "'" : "'" + v.textValue() + "' is a " + o.typeName() + ", not a " + p.type())
                            + "; the " + p.type() + " objects are " + objectsOf(p.type())));
                    return null;
                }
                return o;
        }
        errors.add(new FieldError(field, "expected a " + p.type() + ", got " + v));
        return null;
    }

    static String signature(TaskSchema task) {
        StringBuilder b = new StringBuilder("(");
        for (int i = 0; i < task.params().size(); i++) {
            Param p = task.params().get(i);
            b.append(i > 0 ? ", " : "").append(p.type()).append(' ').append(p.name());
        }
        return b.append(')').toString();
    }
}
