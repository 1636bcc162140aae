package org.triad.dsl.scoping;

import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.scoping.impl.ImportNormalizer;
import org.eclipse.xtext.scoping.impl.ImportedNamespaceAwareLocalScopeProvider;
import org.triad.dsl.triad.DomainModel;
import org.triad.dsl.triad.TriadPackage;

/**
 * Treats {@code domain D;} as an implicit import of {@code D.*}, so the types of class diagram D
 * are visible by their simple names. The name is read from the text, not the resolved reference,
 * because resolving it here would recurse into scoping.
 */
public class DomainImportScopeProvider extends ImportedNamespaceAwareLocalScopeProvider {
	@Override
	protected List<ImportNormalizer> internalGetImportedNamespaceResolvers(EObject context, boolean ignoreCase) {
		List<ImportNormalizer> resolvers = super.internalGetImportedNamespaceResolvers(context, ignoreCase);
		if (context instanceof DomainModel model) {
			for (INode node : NodeModelUtils.findNodesForFeature(model, TriadPackage.Literals.DOMAIN_MODEL__DOMAIN)) {
				String name = NodeModelUtils.getTokenText(node).trim();
				if (!name.isEmpty()) {
					ImportNormalizer resolver = createImportedNamespaceResolver(name + ".*", ignoreCase);
					if (resolver != null) {
						resolvers.add(resolver);
					}
				}
			}
		}
		return resolvers;
	}
}
