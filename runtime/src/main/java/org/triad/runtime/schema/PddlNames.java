package org.triad.runtime.schema;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;

import org.triad.runtime.app.DomainObject;
import org.triad.runtime.app.EnumValue;
import org.triad.runtime.app.Values;

/**
 * The PDDL names of an application's model elements and values. PDDL is case-insensitive and
 * knows only objects, so model values (domain objects, enumeration literals, numbers, strings)
 * become named objects; two values whose names would clash are an error, not a silent merge.
 */
final class PddlNames {
	private final Map<String, Object> valueByName = new LinkedHashMap<>();
	private final Map<Object, String> nameByValue = new HashMap<>();
	private final Map<String, String> typeByName = new LinkedHashMap<>();

	static String predicate(String actor, String property) {
		return lower(actor) + "-" + lower(property);
	}

	static String action(String actor, String action) {
		return lower(actor) + "-" + lower(action);
	}

	static String type(String modelType) {
		return switch (modelType) {
			case "int" -> "t-int";
			case "double" -> "t-double";
			case "String" -> "t-string";
			case "boolean" -> "t-boolean";
			default -> lower(modelType);
		};
	}

	static String variable(String name) {
		return "?" + lower(name);
	}

	static String lower(String s) {
		return s.toLowerCase(Locale.ROOT);
	}

	/** The PDDL object standing for a value, registering it with its model type on first use. */
	String value(Object raw, String modelType) {
		Object v = Values.canonical(raw);
		String known = nameByValue.get(v);
		if (known != null) {
			return known;
		}
		String name;
		String type = modelType;
		if (v instanceof DomainObject o) {
			name = lower(o.name());
			type = o.typeName();
		} else if (v instanceof EnumValue e) {
			name = lower(e.enumeration() + "-" + e.literal());
			type = e.enumeration();
		} else if (v instanceof Integer i) {
			name = "int-" + (i < 0 ? "m" + (-(long) i) : i.toString());
			type = "int";
		} else if (v instanceof Double d) {
			name = "dbl-" + d.toString().replace('-', 'm').replace('.', '-').toLowerCase(Locale.ROOT);
			type = "double";
		} else if (v instanceof String s) {
			name = "str-" + s.toLowerCase(Locale.ROOT).replaceAll("[^a-z0-9]+", "-") + "-" + Integer.toHexString(s.hashCode());
			type = "String";
		} else if (v instanceof Boolean b) {
			name = b ? "true-value" : "false-value";
			type = "boolean";
		} else {
			throw new PddlTranslationException("cannot translate the value " + raw + " to PDDL");
		}
		Object clash = valueByName.get(name);
		if (clash != null) {
			throw new PddlTranslationException("objects '" + clash + "' and '" + raw + "' have the same PDDL name '" + name
					+ "' (PDDL ignores case); rename one of them");
		}
		valueByName.put(name, v);
		nameByValue.put(v, name);
		typeByName.put(name, type);
		return name;
	}

	Object valueOf(String pddlName) {
		return valueByName.get(lower(pddlName));
	}

	Map<String, String> objectsWithTypes() {
		return typeByName;
	}
}
