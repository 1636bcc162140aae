package org.triad.dsl.ide.workspace;

import java.util.function.Function;
import java.util.function.Supplier;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.naming.QualifiedName;
import org.eclipse.xtext.resource.IContainer;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.resource.IResourceDescription;
import org.eclipse.xtext.resource.IResourceDescriptions;
import org.eclipse.xtext.resource.ISelectable;

import com.google.common.collect.Iterables;

/**
 * An index (or container) seen from one application: only the descriptions of files below the
 * application's folder. Queries go to the full index and are filtered, so lookups by name stay
 * as fast as the index's own.
 */
final class ApplicationSlice implements IContainer, IResourceDescriptions {
	private final ISelectable all;
	private final Supplier<Iterable<IResourceDescription>> resources;
	private final Function<URI, IResourceDescription> byUri;
	private final String root;

	private ApplicationSlice(ISelectable all, Supplier<Iterable<IResourceDescription>> resources, Function<URI, IResourceDescription> byUri,
			String root) {
		this.all = all;
		this.resources = resources;
		this.byUri = byUri;
		this.root = root;
	}

	static ApplicationSlice of(IResourceDescriptions index, String root) {
		return new ApplicationSlice(index, index::getAllResourceDescriptions, index::getResourceDescription, root);
	}

	static ApplicationSlice of(IContainer container, String root) {
		return new ApplicationSlice(container, container::getResourceDescriptions, container::getResourceDescription, root);
	}

	private boolean in(URI uri) {
		return ApplicationFolders.contains(root, uri);
	}

	private Iterable<IEObjectDescription> inSlice(Iterable<IEObjectDescription> objects) {
		return Iterables.filter(objects, d -> in(d.getEObjectURI()));
	}

	@Override
	public Iterable<IResourceDescription> getResourceDescriptions() {
		return Iterables.filter(resources.get(), d -> in(d.getURI()));
	}

	@Override
	public Iterable<IResourceDescription> getAllResourceDescriptions() {
		return getResourceDescriptions();
	}

	@Override
	public int getResourceDescriptionCount() {
		return Iterables.size(getResourceDescriptions());
	}

	@Override
	public boolean hasResourceDescription(URI uri) {
		return getResourceDescription(uri) != null;
	}

	@Override
	public IResourceDescription getResourceDescription(URI uri) {
		return in(uri) ? byUri.apply(uri) : null;
	}

	@Override
	public boolean isEmpty() {
		return Iterables.isEmpty(getResourceDescriptions());
	}

	@Override
	public Iterable<IEObjectDescription> getExportedObjects() {
		return inSlice(all.getExportedObjects());
	}

	@Override
	public Iterable<IEObjectDescription> getExportedObjects(EClass type, QualifiedName name, boolean ignoreCase) {
		return inSlice(all.getExportedObjects(type, name, ignoreCase));
	}

	@Override
	public Iterable<IEObjectDescription> getExportedObjectsByType(EClass type) {
		return inSlice(all.getExportedObjectsByType(type));
	}

	@Override
	public Iterable<IEObjectDescription> getExportedObjectsByObject(EObject object) {
		return inSlice(all.getExportedObjectsByObject(object));
	}
}
