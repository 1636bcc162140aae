package org.triad.runtime.app;

import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A state whose objects are instances of the application's generated domain classes ({@code Room},
 * {@code Item}, ...) instead of {@link GenericObject}s, so that generated code that casts its arguments
 * (the ActionExecutor's table, an {@code IRobot}) and hand-written fakes can work on a situation read
 * from a {@code .state} file. Attribute values are set through the generated setters.
 */
public final class GeneratedObjects {
	private final String domainPackage;
	private final ClassLoader loader;

	private GeneratedObjects(String domainPackage, ClassLoader loader) {
		this.domainPackage = domainPackage;
		this.loader = loader;
	}

	/**
	 * The state with generated objects; {@code generatedClass} is any class of the application's generated
	 * package (e.g. {@code HospitalSchema.class}), whose {@code domain} sub-package holds the domain classes.
	 */
	public static State typed(State state, Class<?> generatedClass) {
		return new GeneratedObjects(generatedClass.getPackageName() + ".domain", generatedClass.getClassLoader()).convert(state);
	}

	private State convert(State state) {
		Map<String, DomainObject> byName = new LinkedHashMap<>();
		for (DomainObject o : state.objects().values()) {
			byName.put(o.name(), o instanceof GenericObject g ? instantiate(g) : o);
		}
		State.Builder b = State.builder().objects(byName.values());
		for (Map.Entry<Atom, Object> e : state.values().entrySet()) {
			Atom a = e.getKey();
			List<Object> args = new ArrayList<>();
			for (Object arg : a.args()) {
				args.add(swap(arg, byName));
			}
			b.value(new Atom(a.actor(), a.property(), args), swap(e.getValue(), byName));
		}
		return b.build();
	}

	private static Object swap(Object value, Map<String, DomainObject> byName) {
		return value instanceof GenericObject g ? byName.get(g.name()) : value;
	}

	private DomainObject instantiate(GenericObject g) {
		String className = domainPackage + "." + g.typeName();
		try {
			Class<?> type = Class.forName(className, true, loader);
			if (!DomainObject.class.isAssignableFrom(type) || Modifier.isAbstract(type.getModifiers())) {
				throw new IllegalArgumentException(className + " is not a generated domain class with objects of its own");
			}
			DomainObject o = (DomainObject) type.getConstructor(String.class).newInstance(g.name());
			for (Map.Entry<String, Object> attribute : g.attributes().entrySet()) {
				set(o, attribute.getKey(), attribute.getValue());
			}
			return o;
		} catch (ClassNotFoundException e) {
			throw new IllegalArgumentException("no generated class " + className + " for object '" + g.name()
					+ "': is the situation from the application whose code was generated into " + domainPackage + "?", e);
		} catch (ReflectiveOperationException e) {
			throw new IllegalStateException("cannot create " + className + " '" + g.name() + "': " + e, e);
		}
	}

	private static void set(DomainObject o, String attribute, Object value) throws IllegalAccessException, InvocationTargetException {
		if (value == null) {
			return;
		}
		String setter = "set" + Character.toUpperCase(attribute.charAt(0)) + attribute.substring(1);
		for (Method m : o.getClass().getMethods()) {
			if (m.getName().equals(setter) && m.getParameterCount() == 1) {
				m.invoke(o, javaValue(m.getParameterTypes()[0], value));
				return;
			}
		}
		throw new IllegalArgumentException("generated class " + o.getClass().getName() + " has no " + setter + " for attribute '" + attribute + "'");
	}

	@SuppressWarnings({ "unchecked", "rawtypes" })
	private static Object javaValue(Class<?> type, Object value) {
		if (value instanceof EnumValue e && type.isEnum()) {
			for (Object constant : type.getEnumConstants()) {
				if (((Enum) constant).name().equalsIgnoreCase(e.literal())) {
					return constant;
				}
			}
			throw new IllegalArgumentException(type.getName() + " has no constant " + e.literal());
		}
		if ((type == double.class || type == Double.class) && value instanceof Number n) {
			return n.doubleValue();
		}
		return value;
	}
}
