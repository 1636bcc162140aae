package org.triad.generator.arc

import java.util.List
import org.triad.dsl.arc.ArcPort
import org.triad.dsl.arc.ComponentType
import org.triad.dsl.arc.Direction
import org.triad.dsl.arc.Statement
import org.triad.dsl.semantics.ArcModels

/**
 * The class of an atomic component that runs in time slices ({@code TimedComponent}): MontiArc's
 * synchronous and timed components. Each slice, {@code compute()} takes one message per in port
 * (null when none came; a port's name reads it) and then runs the compute block, or takes the first
 * enabled transition of the automaton's current leaf state. An event automaton (transitions with a
 * trigger port and no stereotype) instead handles every queued message, port by port, then its
 * transitions without a trigger once. The init block and the initial actions run before the first
 * slice. A component that extends another extends its class.
 */
class TimedComponentTemplate {
	val ArcNames names
	val JavaExpressions java

	new(ArcNames names) {
		this.names = names
		this.java = new JavaExpressions(names, true)
	}

	def String className(ComponentType c) {
		names.componentClass(c)
	}

	def String render(ComponentType c) {
		val automaton = ArcModels.automaton(c)
		val parent = ArcModels.parent(c)
		val ports = ArcModels.ownPorts(c)
		val in = ArcModels.ports(c, Direction.IN)
		val flat = if (automaton === null) null else new FlatAutomaton(automaton)
		val event = automaton !== null && automaton.stereotype === null && ArcModels.allTransitions(automaton).exists[trigger !== null]
		val pkg = names.javaPackage(c)
		val superClass = if (parent === null) "TimedComponent" else superName(c, parent)
		'''
			«IF !pkg.empty»
				package «pkg»;

			«ENDIF»
			«FOR i : JavaImports.of(c, newLinkedHashSet("TimedComponent", "InPort", "OutPort"), names.dataTypes)»
				import «i»;
			«ENDFOR»

			/**
			 * Component {@code «ArcModels.qualifiedName(c)»}, generated from its .arc model; do not edit. It runs in time slices.
			«JavaDoc.paragraph(ArcModels.documentation(c))» */
			@SuppressWarnings("unchecked")
			public class «names.componentClass(c)»«typeParameters(c)» extends «superClass» {
				«FOR p : ports»
					«port(p)»
				«ENDFOR»
				«FOR p : c.parameters»
					protected final «names.javaType(p.type)» «names.field(p)»;
				«ENDFOR»
				«FOR v : c.variables»
					protected «names.javaType(v.type)» «names.field(v)»;
				«ENDFOR»
				«IF flat !== null»

					/** The leaf states of the automaton. */
					public enum «names.stateEnum» {
						«FOR s : flat.leaves SEPARATOR ','»
							«names.stateConstant(s)»
						«ENDFOR»
					}

					private «names.stateEnum» «names.stateField» = «names.stateEnum».«names.stateConstant(flat.initialLeaf)»;

					/** The automaton's current leaf state. */
					public final «names.stateEnum» «names.currentStateMethod»() {
						return «names.stateField»;
					}
				«ENDIF»

				public «names.componentClass(c)»(«c.parameters.map[names.javaType(type) + " " + names.field(it)].join(", ")») {
					«IF parent !== null»
						super(«c.parentArguments.map[names.javaArgument(it)].join(", ")»);
					«ENDIF»
					«FOR p : c.parameters»
						this.«names.field(p)» = «names.field(p)»;
					«ENDFOR»
					«FOR v : c.variables.filter[initial !== null]»
						this.«names.field(v)» = «java.expression(v.initial)»;
					«ENDFOR»
				}
				«IF !c.initActions.empty || flat !== null»

					@Override
					protected void initialize() throws Exception {
						«IF parent !== null»
							super.initialize();
						«ENDIF»
						«statements(c.initActions)»
						«IF flat !== null»
							«statements(flat.startActions)»
						«ENDIF»
					}
				«ENDIF»
				«IF !c.computeActions.empty || flat !== null || parent === null»

					@Override
					protected void compute() throws Exception {
						«IF event»
							«FOR p : in»
								for («names.portTypeArgument(p)» «names.handlerParameter(p)»; («names.handlerParameter(p)» = poll(this.«names.portField(p)»)) != null;) {
									«step(flat, p, false)»
								}
							«ENDFOR»
							«IF ArcModels.allTransitions(automaton).exists[trigger === null]»
								«step(flat, null, false)»
							«ENDIF»
						«ELSE»
							«FOR p : in»
								«names.portTypeArgument(p)» «names.handlerParameter(p)» = poll(this.«names.portField(p)»);
							«ENDFOR»
							«IF flat !== null»
								«step(flat, null, true)»
							«ELSE»
								«statements(c.computeActions)»
							«ENDIF»
						«ENDIF»
					}
				«ENDIF»
			}
		'''
	}

	private def String superName(ComponentType c, ComponentType parent) {
		val raw = if (names.javaPackage(parent) == names.javaPackage(c)) names.componentClass(parent) else names.qualifiedComponentClass(parent)
		raw + (if (c.parentTypeArguments.empty) "" else "<" + c.parentTypeArguments.map[names.javaType(trim)].join(", ") + ">")
	}

	private def String typeParameters(ComponentType c) {
		if (c.typeParameters.empty) ""
		else "<" + c.typeParameters.map[name + (if (upperBound === null) "" else " extends " + names.javaType(upperBound.trim))].join(", ") + ">"
	}

	private def String port(ArcPort p) {
		val in = ArcModels.direction(p) == Direction.IN
		val factory = if (in) "inPort" else if (ArcModels.isDelayed(p)) "delayedOutPort" else "outPort"
		'''public final «IF in»InPort«ELSE»OutPort«ENDIF»<«names.portTypeArgument(p)»> «names.portField(p)» = «factory»("«names.runtimePortName(p)»", «names.classLiteral(p)»);'''
	}

	/** One step of the automaton: in the current leaf, the first enabled transition (on {@code trigger}, or any when {@code any}). */
	private def String step(FlatAutomaton flat, ArcPort trigger, boolean any) {
		'''
			switch («names.stateField») {
				«FOR leaf : flat.leaves»
					«val ts = flat.candidates(leaf, trigger, any)»
					«IF !ts.empty»
						case «names.stateConstant(leaf)» -> {
							«FOR t : ts»
								«IF t.guard !== null»if («java.expression(t.guard)») «ENDIF»{
									«statements(flat.actions(leaf, t))»
									«names.stateField» = «names.stateEnum».«names.stateConstant(flat.targetLeaf(t))»;
									break;
								}
							«ENDFOR»
						}
					«ENDIF»
				«ENDFOR»
				default -> {
				}
			}
		'''
	}

	private def String statements(List<Statement> list) {
		java.statements(list)
	}
}
