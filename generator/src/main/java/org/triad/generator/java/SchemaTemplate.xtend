package org.triad.generator.java

import java.util.List
import org.triad.runtime.schema.ActionSchema
import org.triad.runtime.schema.AppSchema
import org.triad.runtime.schema.Effect
import org.triad.runtime.schema.Expr
import org.triad.runtime.schema.GoalSchema
import org.triad.runtime.schema.Param
import org.triad.runtime.schema.PropertySchema
import org.triad.runtime.schema.TaskSchema
import org.triad.runtime.schema.TypeSchema

/**
 * The application schema as Java code: the same {@link AppSchema} that {@code SchemaBuilder} makes
 * from the models, rebuilt without them at runtime. Printed from the built schema, so the two
 * cannot disagree.
 */
class SchemaTemplate {
	val TriadNames names

	new(TriadNames names) {
		this.names = names
	}

	def String schemaClass(AppSchema s) {
		val im = names.imports(names.basePackage, names.schemaClass)
		val body = schemaBody(s, im)
		'''
			package «names.basePackage»;

			«im.declarations»

			«body»
		'''
	}

	private def String schemaBody(AppSchema s, Imports im) {
		val appSchema = im.ref("org.triad.runtime.schema.AppSchema")
		val builder = appSchema + ".Builder"
		'''
			/** What the runtime knows of application {@code «s.name»}: types, actor properties and actions, goals, tasks. Generated: do not edit. */
			public final class «names.schemaClass» {
				public static final «appSchema» «names.schemaField» = «names.schemaBuildMethod»();

				private «names.schemaClass»() {
				}

				private static «appSchema» «names.schemaBuildMethod»() {
					«builder» «names.schemaBuilderVariable» = «appSchema».builder(«JavaLiterals.string(s.name)», «JavaLiterals.string(s.robot)», «JavaLiterals.string(s.world)»);
					«names.schemaPartMethod("types")»(«names.schemaBuilderVariable»);
					«names.schemaPartMethod("properties")»(«names.schemaBuilderVariable»);
					«names.schemaPartMethod("actions")»(«names.schemaBuilderVariable»);
					«names.schemaPartMethod("goals")»(«names.schemaBuilderVariable»);
					«names.schemaPartMethod("tasks")»(«names.schemaBuilderVariable»);
					return «names.schemaBuilderVariable».build();
				}

				private static void «names.schemaPartMethod("types")»(«builder» «names.schemaBuilderVariable») {
					«FOR t : s.types.values»
						«names.schemaBuilderVariable».type(«type(t, im)»);
					«ENDFOR»
				}

				private static void «names.schemaPartMethod("properties")»(«builder» «names.schemaBuilderVariable») {
					«FOR p : s.properties»
						«names.schemaBuilderVariable».property(«property(p, im)»);
					«ENDFOR»
				}

				private static void «names.schemaPartMethod("actions")»(«builder» «names.schemaBuilderVariable») {
					«FOR a : s.actions»
						«names.schemaBuilderVariable».action(«action(a, im)»);
					«ENDFOR»
				}

				private static void «names.schemaPartMethod("goals")»(«builder» «names.schemaBuilderVariable») {
					«FOR g : s.goals.values»
						«names.schemaBuilderVariable».goal(«goal(g, im)»);
					«ENDFOR»
				}

				private static void «names.schemaPartMethod("tasks")»(«builder» «names.schemaBuilderVariable») {
					«FOR t : s.tasks.values»
						«names.schemaBuilderVariable».task(«task(t, im)»);
					«ENDFOR»
				}
			}
		'''
	}

	def String type(TypeSchema t, Imports im) {
		val ts = im.ref("org.triad.runtime.schema.TypeSchema")
		if (t.isEnum)
			'''«ts».ofEnum(«JavaLiterals.string(t.name)», «im.ref("java.util.List")».of(«t.literals.map[JavaLiterals.string(it)].join(', ')»))'''
		else
			'''«ts».ofClass(«JavaLiterals.string(t.name)», «JavaLiterals.string(t.superType)», «t.isAbstract»)'''
	}

	def String property(PropertySchema p, Imports im) '''new «im.ref("org.triad.runtime.schema.PropertySchema")»(«JavaLiterals.string(p.actor)», «JavaLiterals.string(p.name)», «params(p.params, im)», «JavaLiterals.string(p.type)»)'''

	def String action(ActionSchema a, Imports im) '''new «im.ref("org.triad.runtime.schema.ActionSchema")»(«JavaLiterals.string(a.actor)», «JavaLiterals.string(a.name)», «params(a.params, im)»,
		«expr(a.pre, im)»,
		«im.ref("java.util.List")».of(«a.effects.map[effect(im)].join(', ')»),
		«IF a.cost === null»null«ELSE»«expr(a.cost, im)»«ENDIF»)'''

	def String effect(Effect e, Imports im) '''new «im.ref("org.triad.runtime.schema.Effect")»(«expr(e.call, im)», «e.holds», «IF e.value === null»null«ELSE»«expr(e.value, im)»«ENDIF»)'''

	def String goal(GoalSchema g, Imports im) '''new «im.ref("org.triad.runtime.schema.GoalSchema")»(«JavaLiterals.string(g.name)», «params(g.params, im)», «expr(g.condition, im)»)'''

	/** A task by name, for running it by name ({@code TaskRunner.run("Fetch", ...)}). */
	def String task(TaskSchema t, Imports im) '''new «im.ref("org.triad.runtime.schema.TaskSchema")»(«JavaLiterals.string(t.name)», «params(t.params, im)», «im.ref("java.util.List")».of(«t.steps.map[step(im)].join(', ')»))'''

	def String step(TaskSchema.Step st, Imports im) '''new «im.ref("org.triad.runtime.schema.TaskSchema")».Step(«JavaLiterals.string(st.goal)», «im.ref("java.util.List")».of(«st.args.map[expr(im)].join(', ')»))'''

	def String params(List<Param> ps, Imports im) '''«im.ref("java.util.List")».of(«ps.map['''new «im.ref("org.triad.runtime.schema.Param")»(«JavaLiterals.string(name)», «JavaLiterals.string(type)»)'''].join(', ')»)'''

	def dispatch String expr(Expr.And e, Imports im) '''new «exprType(im)».And(«expr(e.left, im)», «expr(e.right, im)»)'''

	def dispatch String expr(Expr.Or e, Imports im) '''new «exprType(im)».Or(«expr(e.left, im)», «expr(e.right, im)»)'''

	def dispatch String expr(Expr.Not e, Imports im) '''new «exprType(im)».Not(«expr(e.operand, im)»)'''

	def dispatch String expr(Expr.Compare e, Imports im) '''new «exprType(im)».Compare(«exprType(im)».Op.«e.op.name», «expr(e.left, im)», «expr(e.right, im)»)'''

	def dispatch String expr(Expr.Arith e, Imports im) '''new «exprType(im)».Arith('«e.op»', «expr(e.left, im)», «expr(e.right, im)»)'''

	def dispatch String expr(Expr.Call e, Imports im) '''new «exprType(im)».Call(«JavaLiterals.string(e.actor)», «JavaLiterals.string(e.property)», «im.ref("java.util.List")».of(«e.args.map[expr(im)].join(', ')»))'''

	def dispatch String expr(Expr.Var e, Imports im) '''new «exprType(im)».Var(«JavaLiterals.string(e.name)»)'''

	def dispatch String expr(Expr.Lit e, Imports im) '''new «exprType(im)».Lit(«JavaLiterals.value(e.value)»)'''

	def dispatch String expr(Expr.EnumLit e, Imports im) '''new «exprType(im)».EnumLit(«JavaLiterals.string(e.enumeration)», «JavaLiterals.string(e.literal)»)'''

	def dispatch String expr(Expr e, Imports im) {
		throw new IllegalArgumentException("not an expression of the runtime schema: " + e)
	}

	private def String exprType(Imports im) {
		im.ref("org.triad.runtime.schema.Expr")
	}
}
