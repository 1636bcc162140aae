package org.triad.generator.java;

import java.lang.reflect.InvocationHandler;
import java.lang.reflect.Method;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.Proxy;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.triad.runtime.app.Atom;
import org.triad.runtime.app.DomainObject;
import org.triad.runtime.app.EnumValue;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.AppSchema;
import org.triad.runtime.schema.PropertySchema;

/**
 * Hand-written stand-ins for a robotics expert's {@code IRobot} and {@code IWorld}: dynamic proxies
 * that answer property queries from a fixed state, list its objects as instances of the generated
 * domain classes, and record the actions they are asked to execute.
 */
final class StateBackedActors {
	final Map<String, DomainObject> objects = new LinkedHashMap<>();
	final List<GroundAction> executed = new ArrayList<>();
	final Object robot;
	final Object world;
	private final State state;
	private final AppSchema schema;

	StateBackedActors(GeneratedCode code, AppSchema schema, State state) throws ReflectiveOperationException {
		this.state = state;
		this.schema = schema;
		for (DomainObject o : state.objects().values()) {
			objects.put(o.name(), (DomainObject) code.load("domain." + o.typeName()).getConstructor(String.class).newInstance(o.name()));
		}
		robot = proxy(code.load("IRobot"), schema.robot());
		world = proxy(code.load("IWorld"), schema.world());
	}

	DomainObject object(String name) {
		return objects.get(name);
	}

	private Object proxy(Class<?> iface, String actor) {
		InvocationHandler h = (p, m, args) -> answer(actor, m, args == null ? List.of() : Arrays.asList(args));
		return Proxy.newProxyInstance(iface.getClassLoader(), new Class<?>[] { iface }, h);
	}

	private Object answer(String actor, Method m, List<Object> args) {
		if (m.getDeclaringClass() == Object.class) {
			throw new UnsupportedOperationException(m.getName());
		}
		if (m.getReturnType() == List.class) {
			String type = ((Class<?>) ((ParameterizedType) m.getGenericReturnType()).getActualTypeArguments()[0]).getSimpleName();
			return objects.values().stream().filter(o -> o.typeName().equals(type)).toList();
		}
		// a model name that is a Java keyword gets a trailing '_' in Java
		String name = schema.action(actor, m.getName()).isPresent() || schema.property(actor, m.getName()).isPresent()
				? m.getName() : m.getName().replaceAll("_$", "");
		if (schema.action(actor, name).isPresent()) {
			executed.add(new GroundAction(actor, name, args));
			return true;
		}
		PropertySchema p = schema.property(actor, name).orElseThrow(() -> new AssertionError("not a property: " + m));
		Atom atom = new Atom(actor, p.name(), args);
		if (p.isBoolean()) {
			return state.holds(atom);
		}
		Object value = state.valueOf(atom).orElse(null);
		if (value == null && (m.getReturnType() == double.class || m.getReturnType() == int.class)) {
			// a number a situation leaves unstated (a distance between waypoints without a corridor): a binding
			// returns some number for it, here 0
			return m.getReturnType() == double.class ? (Object) 0.0 : (Object) 0;
		}
		if (value instanceof EnumValue e && m.getReturnType().isEnum()) {
			return Arrays.stream(m.getReturnType().getEnumConstants()).filter(c -> ((Enum<?>) c).name().equals(e.literal())).findFirst().orElseThrow();
		}
		return value instanceof DomainObject o ? objects.get(o.name()) : value;
	}
}
