package org.triad.generator.java;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Set;

import org.junit.jupiter.api.Test;
import org.triad.dsl.triad.Application;
import org.triad.dsl.triad.TriadFactory;

/** Model names become Java names that compile, and clashing type names are written qualified. */
class TriadNamesTest {
	@Test
	void identifiersEscapeKeywordsAndInvalidCharacters() {
		assertEquals("class_", TriadNames.identifier("class"));
		assertEquals("new_", TriadNames.identifier("new"));
		assertEquals("my_app", TriadNames.identifier("my-app"));
		assertEquals("_3d", TriadNames.identifier("3d"));
		assertEquals("WayPoint", TriadNames.identifier("WayPoint"));
	}

	@Test
	void pluralsOfClassNames() {
		assertEquals("WayPoints", TriadNames.plural("WayPoint"));
		assertEquals("Boxes", TriadNames.plural("Box"));
		assertEquals("Batteries", TriadNames.plural("Battery"));
		assertEquals("Trays", TriadNames.plural("Tray"));
	}

	@Test
	void defaultBasePackageIsTheApplicationNameInLowerCase() {
		Application app = TriadFactory.eINSTANCE.createApplication();
		app.setName("Hospital-Ward");
		assertEquals("generated.hospital_ward", TriadNames.defaultBasePackage(app));
		TriadNames names = new TriadNames(app, "com.example.ward");
		assertEquals("Hospital_WardSchema", names.schemaClass());
		assertEquals("com.example.ward.domain", names.domainPackage());
	}

	@Test
	void badBasePackageIsRejectedWithItsName() {
		Application app = TriadFactory.eINSTANCE.createApplication();
		app.setName("x");
		IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new TriadNames(app, "com.1bad"));
		assertTrue(e.getMessage().contains("'com.1bad'"), e.getMessage());
	}

	@Test
	void importsUseSimpleNamesOnlyWhenUnambiguous() {
		Imports im = new Imports("p.goals", "IsAt", Set.of("IsAt", "Holds"));
		assertEquals("p.domain.IsAt", im.ref("p.domain.IsAt"), "the unit's own name");
		assertEquals("p.domain.Holds", im.ref("p.domain.Holds"), "a class of the same package");
		assertEquals("List", im.ref("java.util.List"));
		assertEquals("p.domain.List", im.ref("p.domain.List"), "java.util.List came first");
		assertEquals("Override", im.ref("p.domain.Override"));
		assertEquals("java.lang.Override", im.ref("java.lang.Override"), "shadowed by the imported domain class");
		assertEquals("String", im.ref("java.lang.String"));
		assertEquals("Room", im.ref("p.domain.Room"));
		assertEquals("int", im.ref("int"));
		assertEquals("import java.util.List;\nimport p.domain.Override;\nimport p.domain.Room;", im.declarations());
	}
}
