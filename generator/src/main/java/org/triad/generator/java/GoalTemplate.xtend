package org.triad.generator.java

import java.util.List
import org.triad.dsl.triad.Goal
import org.triad.dsl.triad.Parameter

/**
 * A goal class per goal model: its parameters bound, satisfied when the goal's condition (taken
 * from the application schema) holds in a state under that binding.
 */
class GoalTemplate {
	val TriadNames names

	new(TriadNames names) {
		this.names = names
	}

	def String goalClass(Goal g) {
		val im = names.imports(names.goalsPackage, names.goalClass(g))
		val body = goalBody(g, im)
		'''
			package «names.goalsPackage»;

			«im.declarations»

			«body»
		'''
	}

	private def String goalBody(Goal g, Imports im) {
		val cls = names.goalClass(g)
		val object = im.ref("java.lang.Object")
		val string = im.ref("java.lang.String")
		val list = im.ref("java.util.List")
		val override = im.ref("java.lang.Override")
		val schema = im.ref(names.qualifiedSchemaClass)
		'''
			/** Goal {@code «g.name»}. Generated: do not edit. */
			public final class «cls» implements «im.ref("org.triad.runtime.app.GoalInstance")» {
				private static final «string» «names.nameConstant» = "«g.name»";
				private static final «im.ref("org.triad.runtime.schema.Expr")» «names.conditionConstant» = «schema».«names.schemaField».goal(«names.nameConstant»).orElseThrow().condition();
				private static final «im.ref("org.triad.runtime.schema.Evaluator")» «names.evaluatorConstant» = new «im.ref("org.triad.runtime.schema.Evaluator")»(«schema».«names.schemaField»);
				«FOR p : g.parameters»
					«parameterField(p, im)»
				«ENDFOR»
				private final «im.ref("java.util.Map")»<«string», «object»> «names.goalBindingField»;

				public «cls»(«constructorParameters(g.parameters, im)») {
					«FOR p : g.parameters»
						«parameterAssignment(p, im)»
					«ENDFOR»
					this.«names.goalBindingField» = «im.ref("java.util.Map")».ofEntries(«FOR p : g.parameters SEPARATOR ', '»«im.ref("java.util.Map")».entry(«JavaLiterals.string(p.name)», this.«names.goalField(p)»)«ENDFOR»);
				}
				«FOR p : g.parameters»

					«parameterGetter(p, im)»
				«ENDFOR»

				@«override»
				public «string» name() {
					return «names.nameConstant»;
				}

				@«override»
				public «list»<«object»> args() {
					return «list».of(«g.parameters.map['this.' + names.goalField(it)].join(', ')»);
				}

				@«override»
				public boolean isSatisfiedIn(«im.ref("org.triad.runtime.app.State")» «names.stateParameter») {
					return «names.evaluatorConstant».holds(«names.conditionConstant», «names.stateParameter», this.«names.goalBindingField»);
				}

				@«override»
				public boolean equals(«object» o) {
					return o instanceof «cls» other && other.args().equals(args());
				}

				@«override»
				public int hashCode() {
					return «im.ref("java.util.Objects")».hash(«names.nameConstant», args());
				}

				@«override»
				public «string» toString() {
					return describe();
				}
			}
		'''
	}

	/** A parameter of a goal or task: a final field. */
	def String parameterField(Parameter p, Imports im) '''
		private final «im.ref(names.javaType(p.type))» «names.goalField(p)»;
	'''

	def String parameterAssignment(Parameter p, Imports im) {
		if (names.javaType(p.type).contains('.'))
			'''this.«names.goalField(p)» = «im.ref("java.util.Objects")».requireNonNull(«names.parameter(p)», "«p.name»");'''
		else
			'''this.«names.goalField(p)» = «names.parameter(p)»;'''
	}

	def String parameterGetter(Parameter p, Imports im) '''
		public «im.ref(names.javaType(p.type))» «names.goalGetter(p)»() {
			return this.«names.goalField(p)»;
		}
	'''

	def String constructorParameters(List<Parameter> ps, Imports im) {
		ps.map[im.ref(names.javaType(type)) + " " + names.parameter(it)].join(", ")
	}
}
