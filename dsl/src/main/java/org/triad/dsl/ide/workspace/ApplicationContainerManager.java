package org.triad.dsl.ide.workspace;

import java.util.List;

import org.eclipse.xtext.resource.IContainer;
import org.eclipse.xtext.resource.IResourceDescription;
import org.eclipse.xtext.resource.IResourceDescriptions;
import org.eclipse.xtext.resource.containers.StateBasedContainerManager;

/** Names resolve within the model file's own application (see {@link ApplicationFolders}). */
public class ApplicationContainerManager extends StateBasedContainerManager {
	@Override
	public List<IContainer> getVisibleContainers(IResourceDescription desc, IResourceDescriptions index) {
		List<IContainer> containers = super.getVisibleContainers(desc, index);
		String root = desc == null ? null : ApplicationFolders.root(desc.getURI(), index);
		return root == null ? containers : containers.stream().map(c -> (IContainer) ApplicationSlice.of(c, root)).toList();
	}
}
