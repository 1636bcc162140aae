package org.triad.generator.arc

import java.util.LinkedHashSet
import org.triad.dsl.arc.ArcPort
import org.triad.dsl.arc.ComponentType
import org.triad.dsl.arc.Connector
import org.triad.dsl.arc.Direction
import org.triad.dsl.arc.PortRef
import org.triad.dsl.arc.Subcomponent
import org.triad.dsl.semantics.ArcModels

/**
 * The class of a composed component: its ports, one field per subcomponent created from the
 * configuration parameters, and one method that makes every connection. It is the component's own
 * class, or its TOP class when hand-written code extends it.
 */
class ComposedComponentTemplate {
	val ArcNames names

	new(ArcNames names) {
		this.names = names
	}

	def String className(ComponentType c, boolean handwritten) {
		if (handwritten) names.topClass(c) else names.componentClass(c)
	}

	def String render(ComponentType c, boolean handwritten) {
		val ports = ArcModels.ports(c)
		val in = ArcModels.ports(c, Direction.IN)
		val runtime = new LinkedHashSet<String>
		runtime.add("ComposedComponent")
		if (!in.empty) runtime.add("InPort")
		if (in.size < ports.size) runtime.add("OutPort")
		val cls = className(c, handwritten)
		val pkg = names.javaPackage(c)
		'''
			«IF !pkg.empty»
				package «pkg»;

			«ENDIF»
			«FOR i : JavaImports.of(c, runtime, names.dataTypes)»
				import «i»;
			«ENDFOR»

			/**
			 * Component {@code «ArcModels.qualifiedName(c)»}, generated from its .arc model; do not edit: ports, subcomponents and connectors.«IF handwritten»
			 * The hand-written subclass {@code «names.componentClass(c)»} extends it (TOP pattern).«ENDIF»
			«JavaDoc.paragraph(ArcModels.documentation(c))» */
			«IF ports.exists[names.isGeneric(it)]»
				@SuppressWarnings("unchecked")
			«ENDIF»
			public «IF handwritten»abstract «ENDIF»class «cls»«names.typeParameters(c)» extends ComposedComponent {
				«FOR p : ports»
					«port(p)»
				«ENDFOR»

				«FOR s : ArcModels.subcomponents(c)»
					public final «subcomponentClass(c, s)» «names.subcomponentField(s)»;
				«ENDFOR»

				«IF handwritten»protected«ELSE»public«ENDIF» «cls»(«c.parameters.map[type + " " + names.parameter(name)].join(", ")») {
					«FOR s : ArcModels.subcomponents(c)»
						«names.subcomponentField(s)» = subcomponent("«s.name»", new «subcomponentConstructor(c, s)»(«s.arguments.map[names.javaArgument(it)].join(", ")»));
					«ENDFOR»
					«names.connectMethod»();
				}

				private void «names.connectMethod»() {
					«FOR con : c.connectors»
						«connector(con)»
					«ENDFOR»
				}
			}
		'''
	}

	private def String port(ArcPort p) {
		val in = ArcModels.direction(p) == Direction.IN
		'''public final «IF in»InPort«ELSE»OutPort«ENDIF»<«names.portTypeArgument(p)»> «names.portField(p)» = «IF in»inPort«ELSE»outPort«ENDIF»("«names.runtimePortName(p)»", «names.classLiteral(p)»);'''
	}

	private def String subcomponentRaw(ComponentType owner, Subcomponent s) {
		val type = ArcModels.type(s)
		if (names.javaPackage(type) == names.javaPackage(owner)) names.componentClass(type) else names.qualifiedComponentClass(type)
	}

	private def String subcomponentClass(ComponentType owner, Subcomponent s) {
		subcomponentRaw(owner, s) + (if (ArcModels.typeArguments(s).empty) "" else "<" + ArcModels.typeArguments(s).map[names.javaType(it.trim)].join(", ") + ">")
	}

	private def String subcomponentConstructor(ComponentType owner, Subcomponent s) {
		subcomponentRaw(owner, s) + (if (ArcModels.typeArguments(s).empty) "" else "<>")
	}

	private def String connector(Connector con) {
		'''connect(«endpoint(con.source)», «con.targets.map[endpoint(it)].join(", ")»);'''
	}

	private def String endpoint(PortRef ref) {
		if (ref.faults) return names.faultsField
		val port = names.portField(ref.port)
		if (ref.subcomponent === null) port else names.subcomponentField(ref.subcomponent) + "." + port
	}
}
