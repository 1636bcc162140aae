package org.triad.service;

import java.util.List;

import org.triad.runtime.schema.AppSchema;
import org.triad.runtime.schema.Param;
import org.triad.runtime.schema.TaskSchema;
import org.triad.runtime.schema.TypeSchema;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * The OpenAPI 3 description of the service, derived from the application's task models: one schema
 * per task ({@code Task.<Name>}), its object parameters as enumerations of the objects the world lists,
 * and the submission as one of them, told apart by {@code task}.
 */
public final class OpenApiDocument {
    private static final JsonNodeFactory JSON = JsonNodeFactory.instance;

    private OpenApiDocument() {
    }

    /** The schema name of a task's submission. */
    public static String schemaName(String task) {
        return "Task." + task;
    }

    public static ObjectNode of(TaskCatalog catalog, String version) {
        AppSchema schema = catalog.schema();
        ObjectNode doc = JSON.objectNode();
        doc.put("openapi", "3.0.3");
        ObjectNode info = doc.putObject("info");
        info.put("title", schema.name() + " tasks (Triad service)");
        info.put("version", version);
        info.put("description", "Tasks of the " + schema.name() + " application, derived from its task models. Submitting needs the submit "
                + "or operator token, operator actions the operator token: 'Authorization: Bearer TOKEN' (or '?token=TOKEN').");
        ObjectNode components = doc.putObject("components");
        ObjectNode schemas = components.putObject("schemas");
        ObjectNode security = components.putObject("securitySchemes");
        security.putObject("bearer").put("type", "http").put("scheme", "bearer");
        security.putObject("queryToken").put("type", "apiKey").put("in", "query").put("name", "token");
        ArrayNode globalSecurity = doc.putArray("security");
        globalSecurity.addObject().putArray("bearer");
        globalSecurity.addObject().putArray("queryToken");

        ObjectNode submission = schemas.putObject("TaskSubmission");
        submission.put("description", "One of the application's tasks with its arguments.");
        ArrayNode oneOf = submission.putArray("oneOf");
        ObjectNode mapping = submission.putObject("discriminator").put("propertyName", "task").putObject("mapping");
        for (TaskSchema task : schema.tasks().values()) {
            String name = schemaName(task.name());
            oneOf.addObject().put("$ref", "#/components/schemas/" + name);
            mapping.put(task.name(), "#/components/schemas/" + name);
            schemas.set(name, taskSchema(catalog, task));
        }
        schemas.set("Task", taskView());
        schemas.set("Event", event());
        schemas.set("Error", error());
        schemas.set("Robot", robot());
        schemas.set("RemoteOperationRequest", request());

        ObjectNode paths = doc.putObject("paths");
        ObjectNode tasks = paths.putObject("/api/tasks");
        ObjectNode list = op(tasks, "get", "listTasks", "The tasks, newest first; ?state=queued|running|completed|aborted|cancelled|done|refused filters.");
        list.putArray("parameters").addObject().put("name", "state").put("in", "query").put("required", false).putObject("schema").put("type", "string");
        response(list, "200", "The tasks", arrayOf("Task"));
        errors(list, "401");
        ObjectNode submit = op(tasks, "post", "submitTask", "Queues a task; it is dispatched to the robot that can finish it soonest.");
        submit.putObject("requestBody").put("required", true).putObject("content").putObject("application/json")
                .putObject("schema").put("$ref", "#/components/schemas/TaskSubmission");
        submit.putArray("parameters").addObject().put("name", "Idempotency-Key").put("in", "header").put("required", false)
                .put("description", "A key of the client's choosing (1-200 characters): repeating a submission with it, e.g. after a lost answer,"
                        + " returns the task stored the first time (200) instead of storing a second one")
                .putObject("schema").put("type", "string").put("maxLength", 200);
        response(submit, "201", "Accepted and stored", ref("Task"));
        response(submit, "200", "Stored before under this Idempotency-Key", ref("Task"));
        errors(submit, "400", "401", "413", "422", "503");

        ObjectNode one = paths.putObject("/api/tasks/{id}");
        one.putArray("parameters").add(idParam());
        response(op(one, "get", "getTask", "A task with its Status history."), "200", "The task", ref("Task"));
        errors((ObjectNode) one.get("get"), "401", "404");
        ObjectNode cancel = op(one, "delete", "cancelTask", "Cancels a queued, running or aborted task.");
        response(cancel, "200", "Cancelled (a running task stops after its current action)", ref("Task"));
        errors(cancel, "401", "404", "409");

        for (String action : List.of("retry", "reassign", "done")) {
            ObjectNode p = paths.putObject("/api/tasks/{id}/" + action);
            p.putArray("parameters").add(idParam());
            ObjectNode o = op(p, "post", action + "Task", switch (action) {
                case "retry" -> "Operator: queues an aborted task again for the same robot.";
                case "reassign" -> "Operator: queues an aborted or queued task again, for the robot named in {\"robot\": NAME} or any robot.";
                default -> "Operator: marks an aborted task as done by hand.";
            });
            if (action.equals("reassign")) {
                ObjectNode body = o.putObject("requestBody").put("required", false).putObject("content").putObject("application/json").putObject("schema");
                body.put("type", "object").putObject("properties").putObject("robot").put("type", "string");
            }
            response(o, "200", "The task", ref("Task"));
            errors(o, "401", "403", "404", "409", "422");
        }
        ObjectNode robots = paths.putObject("/api/robots");
        response(op(robots, "get", "listRobots", "The fleet: each robot's state, current task and plan."), "200", "The robots", arrayOf("Robot"));
        errors((ObjectNode) robots.get("get"), "401");
        ObjectNode building = paths.putObject("/api/building");
        response(op(building, "get", "building", "The building's map: every robot with its pose (mapId: its floor), the layout the first robot with a floor map draws (layout, on layoutMap), and floors: one layout per map id (floor)."),
                "200", "The map", JSON.objectNode().put("type", "object"));
        errors((ObjectNode) building.get("get"), "401");
        ObjectNode floor = paths.putObject("/api/robots/{name}/floor");
        floor.putArray("parameters").addObject().put("name", "name").put("in", "path").put("required", true).putObject("schema").put("type", "string");
        response(op(floor, "get", "robotFloor", "The robot's latest floor map (metres): areas, walls, doors, robots, items, people."), "200", "The map",
                JSON.objectNode().put("type", "object"));
        errors((ObjectNode) floor.get("get"), "401", "404");
        for (String action : List.of("offline", "online")) {
            ObjectNode p = paths.putObject("/api/robots/{name}/" + action);
            p.putArray("parameters").addObject().put("name", "name").put("in", "path").put("required", true).putObject("schema").put("type", "string");
            ObjectNode o = op(p, "post", action + "Robot", action.equals("offline")
                    ? "Operator: takes the robot out of dispatch; its running task is interrupted and queued again."
                    : "Operator: puts the robot back into dispatch.");
            response(o, "200", "The robot", ref("Robot"));
            errors(o, "401", "403", "404");
        }
        ObjectNode traffic = paths.putObject("/api/traffic");
        traffic.putArray("parameters").addObject().put("name", "over").put("in", "query").put("required", false)
                .put("description", "list the waits longer than this many seconds (default 30)").putObject("schema").put("type", "number").put("minimum", 0);
        ObjectNode waiting = JSON.objectNode().put("type", "object");
        ObjectNode wp = waiting.putObject("properties");
        wp.putObject("robot").put("type", "string");
        wp.putObject("seconds").put("type", "number");
        wp.putObject("reason").put("type", "string");
        wp.putObject("resources").put("type", "array").putObject("items").put("type", "string");
        wp.putObject("heldBy").put("type", "array").putObject("items").put("type", "string");
        ObjectNode tw = JSON.objectNode().put("type", "array");
        tw.set("items", waiting);
        response(op(traffic, "get", "listTrafficWaits", "Robots waiting for a corridor, a door or the lift longer than ?over= seconds: for what, behind whom."),
                "200", "The waits, longest first", tw);
        errors((ObjectNode) traffic.get("get"), "400", "401");
        ObjectNode deviceList = paths.putObject("/api/devices");
        ObjectNode device = JSON.objectNode().put("type", "object");
        device.putArray("required").add("kind").add("name").add("state").add("detail");
        ObjectNode dp = device.putObject("properties");
        dp.putObject("kind").put("type", "string").putArray("enum").add("door").add("lift");
        dp.putObject("name").put("type", "string");
        dp.putObject("state").put("type", "string").put("description", "a door's mode (OPEN, CLOSED, MOVING), a lift's motion (STOPPED, MOVING, FAULT)");
        dp.putObject("detail").put("type", "string").put("description", "a lift's floor, destination and door; empty for a door");
        dp.putObject("reason").put("type", "string").put("nullable", true).put("description", "why the device refused or stopped");
        dp.putObject("since").put("type", "string").put("nullable", true).put("description", "the device's timestamp of this state (ISO 8601)");
        ObjectNode dl = JSON.objectNode().put("type", "array");
        dl.set("items", device);
        response(op(deviceList, "get", "listDevices", "The building's doors and lifts as they last reported (empty for robots whose building serves no devices)."),
                "200", "The devices, by kind and name", dl);
        errors((ObjectNode) deviceList.get("get"), "401");
        ObjectNode requests = paths.putObject("/api/requests");
        response(op(requests, "get", "listRequests", "Open remote-operation requests (?all=true: also resolved ones)."), "200", "The requests",
                arrayOf("RemoteOperationRequest"));
        errors((ObjectNode) requests.get("get"), "401");
        ObjectNode events = paths.putObject("/api/events");
        ObjectNode stream = op(events, "get", "events", "Server-sent events: 'task' (a task changed, with its newest Status event), 'robot', 'request'.");
        stream.putObject("responses").putObject("200").put("description", "An event stream").putObject("content").putObject("text/event-stream")
                .putObject("schema").put("type", "string");
        errors(stream, "401", "406");
        ObjectNode audit = paths.putObject("/api/audit");
        ObjectNode auditGet = op(audit, "get", "auditLog", "Operator: who did what when (operator and admin actions, cancellations, failed logins), newest first.");
        response(auditGet, "200", "The newest 1000 entries", JSON.objectNode().put("type", "array").set("items", JSON.objectNode().put("type", "object")));
        errors(auditGet, "401", "403");
        ObjectNode users = paths.putObject("/api/users");
        ObjectNode usersGet = op(users, "get", "listUsers", "Admin: the named users with their roles (revoked ones too).");
        response(usersGet, "200", "The users", JSON.objectNode().put("type", "array").set("items", JSON.objectNode().put("type", "object")));
        errors(usersGet, "401", "403");
        ObjectNode usersPost = op(users, "post", "addUser", "Admin: adds a user {name, role: staff|operator|admin}; the answer has its token, shown only now.");
        ObjectNode userBody = usersPost.putObject("requestBody").put("required", true).putObject("content").putObject("application/json").putObject("schema");
        userBody.put("type", "object").putArray("required").add("name").add("role");
        userBody.putObject("properties").<ObjectNode>set("name", JSON.objectNode().put("type", "string").put("maxLength", 64))
                .set("role", JSON.objectNode().put("type", "string").set("enum", JSON.arrayNode().add("staff").add("operator").add("admin")));
        response(usersPost, "201", "The user and its token", JSON.objectNode().put("type", "object"));
        errors(usersPost, "400", "401", "403", "413", "422");
        ObjectNode user = paths.putObject("/api/users/{name}");
        user.putArray("parameters").addObject().put("name", "name").put("in", "path").put("required", true).putObject("schema").put("type", "string");
        ObjectNode revoke = op(user, "delete", "revokeUser", "Admin: revokes the user; its token is refused from now on.");
        response(revoke, "200", "Revoked", JSON.objectNode().put("type", "object"));
        errors(revoke, "401", "403", "404");
        ObjectNode openapi = paths.putObject("/api/openapi.json");
        ObjectNode self = op(openapi, "get", "openapi", "This document.");
        self.putArray("security");
        response(self, "200", "OpenAPI 3 document", JSON.objectNode().put("type", "object"));
        return doc;
    }

    private static ObjectNode taskSchema(TaskCatalog catalog, TaskSchema task) {
        ObjectNode s = JSON.objectNode();
        s.put("type", "object");
        s.put("description", "Task " + task.name() + TaskCatalog.signature(task) + ": goals "
                + String.join(", ", task.steps().stream().map(TaskSchema.Step::goal).toList()) + ".");
        s.putArray("required").add("task").add("args");
        s.put("additionalProperties", false);
        ObjectNode props = s.putObject("properties");
        props.putObject("task").put("type", "string").putArray("enum").add(task.name());
        props.set("priority", priority());
        ObjectNode args = props.putObject("args");
        args.put("type", "object");
        args.put("additionalProperties", false);
        ArrayNode required = JSON.arrayNode();
        ObjectNode argProps = args.putObject("properties");
        for (Param p : task.params()) {
            required.add(p.name());
            argProps.set(p.name(), paramSchema(catalog, p));
        }
        if (!required.isEmpty()) {
            args.set("required", required);
        }
        return s;
    }

    private static ObjectNode paramSchema(TaskCatalog catalog, Param p) {
        ObjectNode s = JSON.objectNode();
        switch (p.type()) {
            case "boolean" -> s.put("type", "boolean");
            case "int" -> s.put("type", "integer").put("format", "int32");
            case "double" -> s.put("type", "number").put("format", "double");
            case "String" -> s.put("type", "string");
            default -> {
                s.put("type", "string");
                TypeSchema type = catalog.schema().types().get(p.type());
                List<String> values = type != null && type.isEnum() ? type.literals() : catalog.objectsOf(p.type());
                if (!values.isEmpty()) {
                    ArrayNode e = s.putArray("enum");
                    values.forEach(e::add);
                }
                s.put("x-triad-type", p.type());
            }
        }
        s.put("description", p.type() + " " + p.name());
        return s;
    }

    private static ObjectNode priority() {
        return JSON.objectNode().put("type", "integer").put("minimum", TaskCatalog.MIN_PRIORITY).put("maximum", TaskCatalog.MAX_PRIORITY)
                .put("default", 0).put("description", "higher is dispatched first; first come, first served within a priority");
    }

    private static ObjectNode taskView() {
        ObjectNode s = JSON.objectNode().put("type", "object");
        ObjectNode p = s.putObject("properties");
        p.putObject("id").put("type", "integer").put("format", "int64");
        p.putObject("task").put("type", "string");
        p.putObject("args").put("type", "object");
        p.putObject("call").put("type", "string");
        p.putObject("state").put("type", "string").putArray("enum").add("queued").add("running").add("completed").add("aborted").add("cancelled").add("done").add("refused");
        p.putObject("robot").put("type", "string").put("nullable", true);
        p.putObject("preferredRobot").put("type", "string").put("nullable", true);
        p.putObject("reason").put("type", "string").put("nullable", true);
        p.putObject("submittedAt").put("type", "string").put("format", "date-time");
        p.putObject("updatedAt").put("type", "string").put("format", "date-time");
        p.putObject("events").put("type", "array").putObject("items").put("$ref", "#/components/schemas/Event");
        p.set("priority", priority());
        p.putObject("expectedStart").put("type", "string").put("format", "date-time").put("nullable", true)
                .put("description", "queued or running: when it is expected to start, from the median time of recent tasks");
        p.putObject("expectedFinish").put("type", "string").put("format", "date-time").put("nullable", true);
        return s;
    }

    private static ObjectNode event() {
        ObjectNode s = JSON.objectNode().put("type", "object");
        ObjectNode p = s.putObject("properties");
        p.putObject("id").put("type", "integer").put("format", "int64");
        p.putObject("at").put("type", "string").put("format", "date-time");
        p.putObject("kind").put("type", "string");
        p.putObject("robot").put("type", "string").put("nullable", true);
        p.putObject("text").put("type", "string");
        return s;
    }

    private static ObjectNode error() {
        ObjectNode s = JSON.objectNode().put("type", "object");
        s.putArray("required").add("error").add("message");
        ObjectNode p = s.putObject("properties");
        p.putObject("error").put("type", "string");
        p.putObject("message").put("type", "string");
        ObjectNode fields = p.putObject("fields").put("type", "array").putObject("items").put("type", "object");
        ObjectNode fp = fields.putObject("properties");
        fp.putObject("field").put("type", "string");
        fp.putObject("message").put("type", "string");
        return s;
    }

    private static ObjectNode robot() {
        ObjectNode s = JSON.objectNode().put("type", "object");
        ObjectNode p = s.putObject("properties");
        p.putObject("name").put("type", "string");
        p.putObject("online").put("type", "boolean");
        p.putObject("task").put("type", "integer").put("format", "int64").put("nullable", true);
        p.putObject("call").put("type", "string").put("nullable", true);
        p.putObject("plan").put("type", "array").putObject("items").put("type", "string");
        p.putObject("step").put("type", "integer");
        p.putObject("map").put("type", "boolean");
        p.putObject("offlineReason").put("type", "string").put("nullable", true)
                .put("description", "why the robot is out of dispatch: taken offline by the operator, several tasks in a row aborted on it, gone, or refused");
        p.putObject("presence").put("type", "string").putArray("enum").add("online").add("offline").add("gone").add("refused");
        ObjectNode pose = p.putObject("pose").put("type", "object").put("nullable", true)
                .put("description", "where the robot's platform reports it: metres and radians on the map mapId (e.g. a floor)");
        ObjectNode pp = pose.putObject("properties");
        for (String k : List.of("x", "y", "theta")) {
            pp.putObject(k).put("type", "number");
        }
        pp.putObject("mapId").put("type", "string").put("nullable", true);
        ObjectNode battery = p.putObject("battery").put("type", "object").put("nullable", true)
                .put("description", "the battery as the robot's platform reports it: charge in percent, whether it charges");
        battery.putObject("properties").putObject("charge").put("type", "number");
        ((ObjectNode) battery.get("properties")).putObject("charging").put("type", "boolean");
        return s;
    }

    private static ObjectNode request() {
        ObjectNode s = JSON.objectNode().put("type", "object");
        ObjectNode p = s.putObject("properties");
        p.putObject("id").put("type", "integer").put("format", "int64");
        p.putObject("task").put("type", "integer").put("format", "int64");
        p.putObject("call").put("type", "string");
        p.putObject("robot").put("type", "string").put("nullable", true);
        p.putObject("goal").put("type", "string").put("nullable", true);
        p.putObject("reason").put("type", "string");
        p.putObject("raisedAt").put("type", "string").put("format", "date-time");
        p.putObject("resolvedAt").put("type", "string").put("format", "date-time").put("nullable", true);
        p.putObject("resolution").put("type", "string").put("nullable", true);
        return s;
    }

    private static ObjectNode op(ObjectNode path, String method, String id, String summary) {
        ObjectNode o = path.putObject(method);
        o.put("operationId", id);
        o.put("summary", summary);
        return o;
    }

    private static ObjectNode idParam() {
        ObjectNode p = JSON.objectNode().put("name", "id").put("in", "path").put("required", true);
        p.putObject("schema").put("type", "integer").put("format", "int64");
        return p;
    }

    private static ObjectNode ref(String name) {
        return JSON.objectNode().put("$ref", "#/components/schemas/" + name);
    }

    private static ObjectNode arrayOf(String name) {
        ObjectNode a = JSON.objectNode().put("type", "array");
        a.set("items", ref(name));
        return a;
    }

    private static void response(ObjectNode op, String code, String description, ObjectNode schema) {
        ObjectNode responses = op.has("responses") ? (ObjectNode) op.get("responses") : op.putObject("responses");
        responses.putObject(code).put("description", description).putObject("content").putObject("application/json").set("schema", schema);
    }

    private static void errors(ObjectNode op, String... codes) {
        for (String c : codes) {
            response(op, c, switch (c) {
                case "400" -> "Malformed request (not JSON, not an object), or past a limit: JSON depth 32, numbers of 40 characters, strings of 1000";
                case "401" -> "No valid token";
                case "403" -> "The user's role may not do this (operator or admin needed)";
                case "404" -> "No such task, robot or user";
                case "406" -> "Not asked for as text/event-stream";
                case "409" -> "The task is not in a state that allows this";
                case "413" -> "Body larger than 65536 bytes (refused as it is read)";
                case "422" -> "The submission does not fit the task models (per-field errors)";
                default -> "The database is unavailable";
            }, ref("Error"));
        }
    }
}
