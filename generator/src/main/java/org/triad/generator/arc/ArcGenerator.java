package org.triad.generator.arc;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.Function;
import java.util.regex.Pattern;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.generator.AbstractGenerator;
import org.eclipse.xtext.generator.IFileSystemAccess2;
import org.eclipse.xtext.generator.IGeneratorContext;
import org.triad.dsl.arc.ArcModel;
import org.triad.dsl.arc.ComponentType;
import org.triad.dsl.semantics.ArcModels;

/**
 * Java for the component runtime ({@code org.triad.runtime.component}) from .arc models, one class per
 * component: the wiring of a composed component, the automaton or the hand-written behaviour's TOP
 * class of an atomic one. The Xtext generator of the architecture language (see
 * {@link ArcJavaGeneratorSetup}); expects validated models.
 */
public class ArcGenerator extends AbstractGenerator {
	private static final Pattern TRAILING_BLANKS = Pattern.compile("[ \t]+$", Pattern.MULTILINE);
	private static final Pattern EXTRA_BLANK_LINES = Pattern.compile("\n{3,}");

	private final ArcNames names;
	private final Function<ComponentType, HandwrittenCode> handwritten;
	private final AtomicComponentTemplate atomic;
	private final ComposedComponentTemplate composed;
	private final TimedComponentTemplate timed;

	/** For Xtext builders: hand-written code is looked for beside the models ({@link HandwrittenCode#besideModelsOf}). */
	public ArcGenerator() {
		this(new ArcNames());
	}

	public ArcGenerator(ArcNames names) {
		this(HandwrittenCode::besideModelsOf, names);
	}

	/** With one place for hand-written code, whatever the models' location. */
	public ArcGenerator(ArcNames names, HandwrittenCode handwritten) {
		this(c -> handwritten, names);
	}

	private ArcGenerator(Function<ComponentType, HandwrittenCode> handwritten, ArcNames names) {
		this.names = names;
		this.handwritten = handwritten;
		this.atomic = new AtomicComponentTemplate(names);
		this.composed = new ComposedComponentTemplate(names);
		this.timed = new TimedComponentTemplate(names);
	}

	@Override
	public void doGenerate(Resource input, IFileSystemAccess2 fsa, IGeneratorContext context) {
		for (EObject root : input.getContents()) {
			if (root instanceof ArcModel m && m.getComponent() != null) {
				files(m.getComponent()).forEach(fsa::generateFile);
			}
		}
	}

	/** The generated file of one component: path relative to the output folder, and content. */
	public Map<String, String> files(ComponentType c) {
		boolean hand = handwritten.apply(c).has(names.qualifiedComponentClass(c));
		Map<String, String> files = new LinkedHashMap<>();
		if (ArcModels.isComposed(c)) {
			files.put(names.javaFile(c, composed.className(c, hand)), tidy(composed.render(c, hand)));
		} else if (ArcModels.isTimed(c)) {
			files.put(names.javaFile(c, timed.className(c)), tidy(timed.render(c)));
		} else {
			files.put(names.javaFile(c, atomic.className(c, hand)), tidy(atomic.render(c, hand)));
		}
		return files;
	}

	/** Templates indent blank lines too; generated code carries no trailing blanks and no runs of blank lines. */
	private static String tidy(String java) {
		return EXTRA_BLANK_LINES.matcher(TRAILING_BLANKS.matcher(java).replaceAll("")).replaceAll("\n\n");
	}
}
