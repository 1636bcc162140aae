package org.triad.dsl.scoping;

import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.scoping.IScope;
import org.eclipse.xtext.scoping.impl.ImportNormalizer;
import org.eclipse.xtext.scoping.impl.ImportedNamespaceAwareLocalScopeProvider;
import org.triad.dsl.triad.DomainModel;
import org.triad.dsl.triad.Expression;
import org.triad.dsl.triad.TriadPackage;

/**
 * Treats {@code domain D;} as an implicit import of {@code D.*}, so the types of class diagram D
 * are visible by their simple names. The name is read from the text, not the resolved reference,
 * because resolving it here would recurse into scoping.
 * <p>
 * Expressions declare no names and import nothing, so a reference inside an expression sees the
 * same scope as the element that holds the whole expression. The scope is computed from there:
 * Xtext's provider would otherwise build one scope layer per enclosing expression, recursively,
 * which for a 10,000-term conjunction means 10,000 nested calls per reference (quadratic time
 * and a stack overflow).
 */
public class DomainImportScopeProvider extends ImportedNamespaceAwareLocalScopeProvider {
	@Override
	public IScope getScope(EObject context, EReference reference) {
		return super.getScope(outsideExpressions(context), reference);
	}

	static EObject outsideExpressions(EObject context) {
		EObject c = context;
		while (c instanceof Expression && c.eContainer() != null) {
			c = c.eContainer();
		}
		return c;
	}

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
