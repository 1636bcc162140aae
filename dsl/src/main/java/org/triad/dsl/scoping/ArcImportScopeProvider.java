package org.triad.dsl.scoping;

import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.scoping.impl.ImportNormalizer;
import org.eclipse.xtext.scoping.impl.ImportedNamespaceAwareLocalScopeProvider;
import org.triad.dsl.arc.ArcModel;

/**
 * Components of the same package are visible by simple name, as in MontiArc and Java: the
 * package of an .arc file is an implicit wildcard import.
 */
public class ArcImportScopeProvider extends ImportedNamespaceAwareLocalScopeProvider {
	@Override
	protected List<ImportNormalizer> internalGetImportedNamespaceResolvers(EObject context, boolean ignoreCase) {
		List<ImportNormalizer> resolvers = super.internalGetImportedNamespaceResolvers(context, ignoreCase);
		if (context instanceof ArcModel model && model.getName() != null && !model.getName().isBlank()) {
			ImportNormalizer resolver = createImportedNamespaceResolver(model.getName() + ".*", ignoreCase);
			if (resolver != null) {
				resolvers.add(resolver);
			}
		}
		return resolvers;
	}
}
