package org.triad.runtime.schema;

/** A typed parameter; {@code type} is a class or enumeration name or boolean/int/double/String. */
public record Param(String name, String type) {
}
