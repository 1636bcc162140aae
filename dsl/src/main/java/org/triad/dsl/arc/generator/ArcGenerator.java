package org.triad.dsl.arc.generator;

import java.util.LinkedHashMap;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.generator.AbstractGenerator;
import org.eclipse.xtext.generator.IFileSystemAccess2;
import org.eclipse.xtext.generator.IGeneratorContext;
import org.triad.dsl.arc.ArcModel;
import org.triad.dsl.arc.ComponentType;
import org.triad.dsl.semantics.ArcModels;

/**
 * Java for the component runtime ({@code org.triad.runtime.component}) from .arc models: the TOP
 * class of an atomic component, the wiring class of a composed one. Expects validated models.
 */
public class ArcGenerator extends AbstractGenerator {
	private final ArcNames names;
	private final AtomicComponentTemplate atomic;
	private final ComposedComponentTemplate composed;

	/**
	 * For Xtext's generator infrastructure (IGenerator2 binding, e.g. xtext-maven-plugin), which
	 * cannot pass arguments: the base Java package comes from the system property
	 * {@code triad.arc.basePackage} (default none).
	 */
	public ArcGenerator() {
		this(new ArcNames(System.getProperty("triad.arc.basePackage", "")));
	}

	public ArcGenerator(ArcNames names) {
		this.names = names;
		this.atomic = new AtomicComponentTemplate(names);
		this.composed = new ComposedComponentTemplate(names);
	}

	@Override
	public void doGenerate(Resource input, IFileSystemAccess2 fsa, IGeneratorContext context) {
		for (EObject root : input.getContents()) {
			if (root instanceof ArcModel m && m.getComponent() != null) {
				files(m.getComponent()).forEach(fsa::generateFile);
			}
		}
	}

	/** The generated files of one component: path relative to the output folder, and content. */
	public Map<String, String> files(ComponentType c) {
		Map<String, String> files = new LinkedHashMap<>();
		if (ArcModels.isComposed(c)) {
			files.put(names.javaFile(c, names.componentClass(c)), composed.render(c));
		} else {
			files.put(names.javaFile(c, names.topClass(c)), atomic.render(c));
		}
		return files;
	}
}
