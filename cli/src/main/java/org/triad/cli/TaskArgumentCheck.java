package org.triad.cli;

import java.util.List;

import org.triad.runtime.app.DomainObject;
import org.triad.runtime.app.EnumValue;
import org.triad.runtime.schema.AppSchema;
import org.triad.runtime.schema.Param;
import org.triad.runtime.schema.TaskSchema;
import org.triad.runtime.schema.TypeSchema;

/**
 * A task call's arguments against the task's parameter types, before anything runs: an Item where
 * a Person is wanted is refused at once, naming the parameter and both types, like a wrong argument
 * count, instead of failing deep inside planning.
 */
final class TaskArgumentCheck {
	private TaskArgumentCheck() {
	}

	/** Throws a {@link ModelSession.UserError} for the first argument that does not fit its parameter. */
	static void check(AppSchema schema, String taskName, List<Object> args) {
		TaskSchema task = schema.task(taskName).orElse(null);
		if (task == null || task.params().size() != args.size()) {
			return; // an unknown task and a wrong count are reported by the task instance itself
		}
		for (int i = 0; i < args.size(); i++) {
			Param param = task.params().get(i);
			Object arg = args.get(i);
			if (!fits(schema, param.type(), arg)) {
				throw new ModelSession.UserError("task " + taskName + ": parameter '" + param.name() + "' is " + article(param.type())
						+ ", but '" + arg + "' is " + article(typeOf(arg)));
			}
		}
	}

	static boolean fits(AppSchema schema, String type, Object arg) {
		return switch (type) {
			case "boolean" -> arg instanceof Boolean;
			case "int" -> arg instanceof Integer;
			case "double" -> arg instanceof Double || arg instanceof Integer;
			case "String" -> arg instanceof String;
			default -> {
				TypeSchema t = schema.types().get(type);
				if (t != null && t.isEnum()) {
					yield arg instanceof EnumValue v && v.enumeration().equals(type) && t.literals().contains(v.literal());
				}
				yield arg instanceof DomainObject o && schema.isSubtype(o.typeName(), type);
			}
		};
	}

	/** The model's name for the type of a value given on the command line. */
	static String typeOf(Object arg) {
		if (arg instanceof DomainObject o) {
			return o.typeName();
		}
		if (arg instanceof EnumValue v) {
			return v.enumeration();
		}
		if (arg instanceof Integer) {
			return "int";
		}
		if (arg instanceof Double) {
			return "double";
		}
		return arg instanceof Boolean ? "boolean" : "String";
	}

	private static String article(String type) {
		return ("AEIOUaeiou".indexOf(type.charAt(0)) >= 0 ? "an " : "a ") + type;
	}
}
