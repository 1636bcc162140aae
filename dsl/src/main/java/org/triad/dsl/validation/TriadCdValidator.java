package org.triad.dsl.validation;

import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;

import org.eclipse.xtext.validation.Check;
import org.triad.dsl.triad.Attribute;
import org.triad.dsl.triad.ClassDiagram;
import org.triad.dsl.triad.DomainClass;
import org.triad.dsl.triad.DomainType;
import org.triad.dsl.triad.EnumLiteral;
import org.triad.dsl.triad.Enumeration;
import org.triad.dsl.typing.TriadTypeSystem;

/** Rules of class diagrams; codes in {@link CdIssueCodes}. */
public class TriadCdValidator extends AbstractTriadCdValidator {

	@Check
	public void checkUniqueTypes(ClassDiagram cd) {
		Set<String> seen = new HashSet<>();
		for (DomainType t : cd.getTypes()) {
			if (t.getName() != null && !seen.add(t.getName())) {
				error("duplicate type '" + t.getName() + "' in class diagram '" + cd.getName() + "'", t, P.getNamedElement_Name(),
						CdIssueCodes.DUPLICATE_TYPE);
			}
		}
	}

	@Check
	public void checkInheritance(DomainClass c) {
		DomainClass current = c.getSuperType();
		Set<DomainClass> seen = new HashSet<>();
		while (current != null && !current.eIsProxy() && seen.add(current)) {
			if (current == c) {
				error("cyclic inheritance: '" + c.getName() + "' is its own superclass", c, P.getDomainClass_SuperType(),
						CdIssueCodes.CYCLIC_INHERITANCE);
				return;
			}
			current = current.getSuperType();
		}
	}

	@Check
	public void checkAttributes(DomainClass c) {
		Map<String, DomainClass> inherited = new HashMap<>();
		for (DomainClass sup : TriadTypeSystem.superClassesAndSelf(c)) {
			if (sup != c) {
				for (Attribute a : sup.getAttributes()) {
					inherited.putIfAbsent(a.getName(), sup);
				}
			}
		}
		Set<String> own = new HashSet<>();
		for (Attribute a : c.getAttributes()) {
			if (a.getName() == null) {
				continue;
			}
			if (!own.add(a.getName())) {
				error("duplicate attribute '" + a.getName() + "' in class '" + c.getName() + "'", a, P.getNamedElement_Name(),
						CdIssueCodes.DUPLICATE_ATTRIBUTE);
			} else if (inherited.containsKey(a.getName())) {
				error("attribute '" + a.getName() + "' of class '" + c.getName() + "' is already inherited from '"
						+ inherited.get(a.getName()).getName() + "'", a, P.getNamedElement_Name(), CdIssueCodes.DUPLICATE_ATTRIBUTE);
			}
		}
	}

	@Check
	public void checkLiterals(Enumeration e) {
		if (e.getLiterals().isEmpty()) {
			warning("enumeration '" + e.getName() + "' has no literals", e, P.getNamedElement_Name(), CdIssueCodes.EMPTY_ENUM);
		}
		Set<String> seen = new HashSet<>();
		for (EnumLiteral l : e.getLiterals()) {
			if (l.getName() != null && !seen.add(l.getName())) {
				error("duplicate literal '" + l.getName() + "' in enumeration '" + e.getName() + "'", l, P.getNamedElement_Name(),
						CdIssueCodes.DUPLICATE_LITERAL);
			}
		}
	}
}
