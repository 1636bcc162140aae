package org.triad.generator.java;

import java.util.List;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.generator.AbstractGenerator;
import org.eclipse.xtext.generator.IFileSystemAccess2;
import org.eclipse.xtext.generator.IGeneratorContext;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.triad.Application;
import org.triad.dsl.triad.ClassDiagram;

/**
 * The Java generator as an Xtext {@code IGenerator2}, for the {@code xtext-maven-plugin} and other
 * Xtext builders. Bound to the class-diagram language (see {@link TriadJavaGeneratorSetup}): the class
 * diagram's resource generates the whole application, assembled by {@link ApplicationAssembler} from
 * every model in its resource set, because IRobot, IWorld, the schema and the behaviours depend on
 * all of them. An application that breaks the structure rule generates nothing: the validators have
 * reported the violation on the offending element already.
 */
public class TriadApplicationGenerator extends AbstractGenerator {
	@Override
	public void doGenerate(Resource input, IFileSystemAccess2 fsa, IGeneratorContext context) {
		if (input.getContents().isEmpty() || !(input.getContents().get(0) instanceof ClassDiagram)) {
			return;
		}
		EcoreUtil.resolveAll(input.getResourceSet());
		List<Resource> resources = List.copyOf(input.getResourceSet().getResources());
		if (!ApplicationAssembler.violations(resources).isEmpty()) {
			return;
		}
		Application app = ApplicationAssembler.assemble(resources);
		for (TriadJavaGenerator.GeneratedFile f : TriadJavaGenerator.files(app, TriadNames.defaultBasePackage(app))) {
			fsa.generateFile(f.relativePath().toString().replace('\\', '/'), f.content());
		}
	}
}
