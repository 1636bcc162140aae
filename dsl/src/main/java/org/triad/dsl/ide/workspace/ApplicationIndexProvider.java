package org.triad.dsl.ide.workspace;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.resource.IResourceDescriptions;
import org.eclipse.xtext.resource.impl.ResourceDescriptionsProvider;

/**
 * The index as the checks of one model file see it: its own application only (see
 * {@link ApplicationFolders}), so two applications in one workspace do not clash over "one robot
 * per application" or application-wide names.
 */
public class ApplicationIndexProvider extends ResourceDescriptionsProvider {
	@Override
	public IResourceDescriptions getResourceDescriptions(Resource resource) {
		IResourceDescriptions all = super.getResourceDescriptions(resource);
		String root = ApplicationFolders.root(resource.getURI(), all);
		return root == null ? all : ApplicationSlice.of(all, root);
	}
}
