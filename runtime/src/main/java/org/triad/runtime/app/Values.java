package org.triad.runtime.app;

/** The one representation of each value in states and atoms, so equal values compare equal. */
public final class Values {
	private Values() {
	}

	/** Java enum constants become {@link EnumValue}s; {@code int}-valued doubles stay doubles; other values are kept. */
	public static Object canonical(Object value) {
		if (value instanceof Enum<?> e) {
			return new EnumValue(e.getDeclaringClass().getSimpleName(), e.name());
		}
		if (value instanceof Long l && l >= Integer.MIN_VALUE && l <= Integer.MAX_VALUE) {
			return l.intValue();
		}
		return value;
	}

	/** Equality of model values: numbers by value (1 == 1.0), everything else by {@code equals}. */
	public static boolean same(Object a, Object b) {
		Object x = canonical(a);
		Object y = canonical(b);
		if (x instanceof Number n && y instanceof Number m) {
			return n.doubleValue() == m.doubleValue();
		}
		return x == null ? y == null : x.equals(y);
	}
}
