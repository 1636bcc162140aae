package org.triad.dsl.ide.symbols;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.lsp4j.SymbolKind;
import org.eclipse.xtext.ide.server.symbol.DocumentSymbolMapper.DocumentSymbolKindProvider;
import org.triad.dsl.arc.ArcPackage;
import org.triad.dsl.triad.TriadPackage;

import com.google.inject.Singleton;

/**
 * The LSP symbol kind of each model element, so outlines and symbol pickers show tasks, goals,
 * actors, actions, properties and classes with their own icons instead of "property" for all.
 */
@Singleton
public class ModelSymbolKinds extends DocumentSymbolKindProvider {
	private static final TriadPackage T = TriadPackage.eINSTANCE;
	private static final ArcPackage A = ArcPackage.eINSTANCE;

	@Override
	protected SymbolKind getSymbolKind(EClass c) {
		if (c == null) {
			return SymbolKind.Property;
		}
		if (c == T.getClassDiagram()) {
			return SymbolKind.Package;
		}
		if (c == T.getDomainClass()) {
			return SymbolKind.Class;
		}
		if (c == T.getEnumeration()) {
			return SymbolKind.Enum;
		}
		if (c == T.getEnumLiteral()) {
			return SymbolKind.EnumMember;
		}
		if (c == T.getAttribute()) {
			return SymbolKind.Field;
		}
		if (c == T.getActor()) {
			return SymbolKind.Object;
		}
		if (c == T.getProperty()) {
			return SymbolKind.Property;
		}
		if (c == T.getAction()) {
			return SymbolKind.Method;
		}
		if (c == T.getGoal()) {
			return SymbolKind.Event;
		}
		if (c == T.getTask()) {
			return SymbolKind.Function;
		}
		if (c == T.getParameter() || c == A.getConfigParameter()) {
			return SymbolKind.Variable;
		}
		if (c == T.getSituation()) {
			return SymbolKind.Namespace;
		}
		if (c == T.getSituationObject()) {
			return SymbolKind.Constant;
		}
		if (c == A.getComponentType()) {
			return SymbolKind.Class;
		}
		if (c == A.getArcPort()) {
			return SymbolKind.Interface;
		}
		if (c == A.getSubcomponent()) {
			return SymbolKind.Field;
		}
		if (c == A.getAutomatonState()) {
			return SymbolKind.EnumMember;
		}
		if (c == A.getArcModel()) {
			return SymbolKind.Package;
		}
		return SymbolKind.Property;
	}
}
