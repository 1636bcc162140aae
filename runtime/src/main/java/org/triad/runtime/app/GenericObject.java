package org.triad.runtime.app;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * A domain object for tools that run models without generated classes (dry runs, PDDL export):
 * its type is named, its attribute values kept by name. Equal to a generated object of the same
 * type and name.
 */
public final class GenericObject extends DomainObject {
	private final String typeName;
	private final Map<String, Object> attributes;

	public GenericObject(String name, String typeName, Map<String, Object> attributes) {
		super(name);
		if (typeName == null || typeName.isBlank()) {
			throw new IllegalArgumentException("object '" + name + "' needs a type");
		}
		this.typeName = typeName;
		this.attributes = Collections.unmodifiableMap(new LinkedHashMap<>(attributes));
	}

	@Override
	public String typeName() {
		return typeName;
	}

	public Map<String, Object> attributes() {
		return attributes;
	}

	@Override
	public Object attribute(String attribute) {
		return attributes.get(attribute);
	}
}
