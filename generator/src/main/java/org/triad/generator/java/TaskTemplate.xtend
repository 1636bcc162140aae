package org.triad.generator.java

import org.triad.dsl.triad.BooleanLiteral
import org.triad.dsl.triad.DecimalLiteral
import org.triad.dsl.triad.MemberRef
import org.triad.dsl.triad.Expression
import org.triad.dsl.triad.GoalReference
import org.triad.dsl.triad.IntLiteral
import org.triad.dsl.triad.Parameter
import org.triad.dsl.triad.StringLiteral
import org.triad.dsl.triad.Task
import org.triad.dsl.triad.ValueRef

/** A task class per task model: its parameters bound, its goals instantiated in order. */
class TaskTemplate {
	val TriadNames names
	val GoalTemplate goals

	new(TriadNames names) {
		this.names = names
		this.goals = new GoalTemplate(names)
	}

	def String taskClass(Task t) {
		val im = names.imports(names.tasksPackage, names.taskClass(t))
		val body = taskBody(t, im)
		'''
			package «names.tasksPackage»;

			«im.declarations»

			«body»
		'''
	}

	private def String taskBody(Task t, Imports im) {
		val cls = names.taskClass(t)
		val object = im.ref("java.lang.Object")
		val string = im.ref("java.lang.String")
		val list = im.ref("java.util.List")
		val override = im.ref("java.lang.Override")
		'''
			/** Task {@code «t.name»}. Generated: do not edit. */
			public final class «cls» implements «im.ref("org.triad.runtime.app.TaskInstance")» {
				«FOR p : t.parameters»
					«goals.parameterField(p, im)»
				«ENDFOR»

				public «cls»(«goals.constructorParameters(t.parameters, im)») {
					«FOR p : t.parameters»
						«goals.parameterAssignment(p, im)»
					«ENDFOR»
				}
				«FOR p : t.parameters»

					«goals.parameterGetter(p, im)»
				«ENDFOR»

				@«override»
				public «string» name() {
					return "«t.name»";
				}

				@«override»
				public «list»<«object»> args() {
					return «list».of(«t.parameters.map['this.' + names.goalField(it)].join(', ')»);
				}

				@«override»
				public «list»<«im.ref("org.triad.runtime.app.GoalInstance")»> goals() {
					return «list».of(«t.steps.map[goalReference(im)].join(', ')»);
				}

				@«override»
				public «string» toString() {
					return describe();
				}
			}
		'''
	}

	/** One step of a task: its goal instantiated with the step's arguments. */
	def String goalReference(GoalReference r, Imports im) '''new «im.ref(names.qualifiedGoalClass(r.goal))»(«r.arguments.map[argument(im)].join(', ')»)'''

	def dispatch String argument(ValueRef v, Imports im) {
		val value = v.value
		if (value instanceof Parameter) '''this.«names.goalField(value)»'''
		else throw new IllegalArgumentException("a task argument must be a task parameter or a literal: " + value.name)
	}

	def dispatch String argument(BooleanLiteral l, Imports im) '''«l.value»'''

	def dispatch String argument(IntLiteral l, Imports im) '''«l.value»'''

	def dispatch String argument(DecimalLiteral l, Imports im) '''«Double.toString(l.value)»'''

	def dispatch String argument(StringLiteral l, Imports im) '''«JavaLiterals.string(l.value)»'''

	def dispatch String argument(MemberRef r, Imports im) '''«im.ref(names.qualifiedDomainClass(r.owner as org.triad.dsl.triad.Enumeration))».«names.enumConstant(r.member as org.triad.dsl.triad.EnumLiteral)»'''

	def dispatch String argument(Expression e, Imports im) {
		throw new IllegalArgumentException("a task argument must be a task parameter or a literal, not " + e.eClass.name)
	}
}
