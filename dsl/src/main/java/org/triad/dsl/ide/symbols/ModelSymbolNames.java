package org.triad.dsl.ide.symbols;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.ide.server.symbol.DocumentSymbolMapper.DocumentSymbolNameProvider;
import org.eclipse.xtext.naming.QualifiedName;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.util.SimpleAttributeResolver;

import com.google.inject.Singleton;

/**
 * A symbol's name as written at its declaration ({@code dst}, not {@code GoTo.dst}): the outline
 * already shows where it sits. Workspace symbols keep the qualified name, which tells them apart.
 */
@Singleton
public class ModelSymbolNames extends DocumentSymbolNameProvider {
	@Override
	public String getName(EObject object) {
		String name = object == null ? null : SimpleAttributeResolver.NAME_RESOLVER.apply(object);
		return name != null ? name : super.getName(object);
	}

	@Override
	public String getName(IEObjectDescription description) {
		QualifiedName name = description == null ? null : description.getName();
		return name == null ? null : name.toString();
	}
}
