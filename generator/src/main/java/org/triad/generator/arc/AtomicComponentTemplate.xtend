package org.triad.generator.arc

import java.util.LinkedHashSet
import java.util.List
import org.triad.dsl.arc.ArcPort
import org.triad.dsl.arc.Automaton
import org.triad.dsl.arc.ComponentType
import org.triad.dsl.arc.Direction
import org.triad.dsl.arc.Transition
import org.triad.dsl.semantics.ArcModels

/**
 * The class of an atomic component: typed ports and its behaviour. With an automaton, the behaviour
 * is generated (states, variables, one handler per incoming port that takes the first enabled
 * transition, then transitions without a trigger while one is enabled); the class is the component's
 * own, or its TOP class when hand-written code refines it. Without an automaton the behaviour is
 * hand-written: the TOP class declares one abstract handler per incoming port.
 */
class AtomicComponentTemplate {
	val ArcNames names
	val JavaExpressions java

	new(ArcNames names) {
		this.names = names
		this.java = new JavaExpressions(names)
	}

	/** The class's simple name: the component's, or its TOP class's when hand-written code extends it or must supply the behaviour. */
	def String className(ComponentType c, boolean handwritten) {
		if (handwritten || ArcModels.automaton(c) === null) names.topClass(c) else names.componentClass(c)
	}

	def String render(ComponentType c, boolean handwritten) {
		val automaton = ArcModels.automaton(c)
		val ports = ArcModels.ports(c)
		val in = ArcModels.ports(c, Direction.IN)
		val runtime = new LinkedHashSet<String>
		runtime.add("AtomicComponent")
		if (!in.empty) runtime.add("InPort")
		if (in.size < ports.size) runtime.add("OutPort")
		val cls = className(c, handwritten)
		val open = automaton === null || handwritten
		val pkg = names.javaPackage(c)
		'''
			«IF !pkg.empty»
				package «pkg»;

			«ENDIF»
			«FOR i : JavaImports.of(c, runtime, names.dataTypes)»
				import «i»;
			«ENDFOR»

			/**
			 * Component {@code «ArcModels.qualifiedName(c)»}, generated from its .arc model; do not edit.
			 * «behaviour(c, automaton !== null, handwritten)»
			«JavaDoc.paragraph(ArcModels.documentation(c))» */
			«IF ports.exists[names.isGeneric(it)]»
				@SuppressWarnings("unchecked")
			«ENDIF»
			public «IF open»abstract «ENDIF»class «cls»«names.typeParameters(c)» extends AtomicComponent {
				«FOR p : ports»
					«port(p)»
				«ENDFOR»
				«IF automaton === null»

					protected «cls»() {
						«FOR p : in»
							on(«names.portField(p)», this::«names.handler(p)»);
						«ENDFOR»
					}
					«FOR p : in»

						protected abstract void «names.handler(p)»(«names.portTypeArgument(p)» «names.handlerParameter()») throws Exception;
					«ENDFOR»
				«ELSE»
					«automatonMembers(c, automaton, cls, handwritten)»
				«ENDIF»
			}
		'''
	}

	private def String behaviour(ComponentType c, boolean automaton, boolean handwritten) {
		if (!automaton)
			"Its behaviour is the hand-written subclass {@code " + names.componentClass(c) + "}: one handler per incoming port (TOP pattern)."
		else if (handwritten)
			"Its behaviour is the model's automaton; the hand-written subclass {@code " + names.componentClass(c) + "} refines it (TOP pattern)."
		else
			"Its behaviour is the model's automaton."
	}

	private def String port(ArcPort p) {
		val in = ArcModels.direction(p) == Direction.IN
		'''public final «IF in»InPort«ELSE»OutPort«ENDIF»<«names.portTypeArgument(p)»> «names.portField(p)» = «IF in»inPort«ELSE»outPort«ENDIF»("«names.runtimePortName(p)»", «names.classLiteral(p)»);'''
	}

	private def String automatonMembers(ComponentType c, Automaton a, String cls, boolean handwritten) {
		val initial = ArcModels.initialState(a)
		val completions = a.transitions.filter[trigger === null].toList
		'''

			/** The states of the automaton. */
			public enum «names.stateEnum» {
				«FOR s : a.states SEPARATOR ','»
					«names.stateConstant(s)»
				«ENDFOR»
			}
			«FOR p : c.parameters»
				protected final «p.type» «names.field(p)»;
			«ENDFOR»
			«FOR v : c.variables»
				protected «v.type» «names.field(v)»;
			«ENDFOR»
			private «names.stateEnum» «names.stateField» = «names.stateEnum».«names.stateConstant(initial)»;
			«IF !completions.empty»
				private boolean «names.startedField»;
			«ENDIF»

			«IF handwritten»protected«ELSE»public«ENDIF» «cls»(«c.parameters.map[type + " " + names.field(it)].join(", ")») {
				«FOR p : c.parameters»
					this.«names.field(p)» = «names.field(p)»;
				«ENDFOR»
				«FOR v : c.variables.filter[initial !== null]»
					this.«names.field(v)» = «java.expression(v.initial)»;
				«ENDFOR»
				«FOR p : ArcModels.ports(c, Direction.IN)»
					on(«names.portField(p)», this::«names.handler(p)»);
				«ENDFOR»
			}

			/** The automaton's current state. */
			public final «names.stateEnum» «names.currentStateMethod»() {
				return «names.stateField»;
			}
			«FOR p : ArcModels.ports(c, Direction.IN)»

				«handler(c, a, p, !completions.empty)»
			«ENDFOR»

			/**
			 * A message on {@code port} that no transition of the current state takes. It is a fault (the
			 * runtime reports it) unless a subclass decides otherwise.
			 */
			protected void «names.unhandledMethod»(String port, Object message) throws Exception {
				throw new IllegalStateException("no transition of state " + «names.stateField» + " of «c.name» takes " + message + " on port " + port);
			}
			«IF !completions.empty»

				private void «names.startMethod»() {
					if (!«names.startedField») {
						«names.startedField» = true;
						«names.completeMethod»();
					}
				}

				/** Takes transitions without a trigger while one is enabled. */
				private void «names.completeMethod»() {
					for (int taken = 0; «names.completeOnceMethod»(); taken++) {
						if (taken == «ArcNames.MAX_COMPLETIONS») {
							throw new IllegalStateException("«c.name» took «ArcNames.MAX_COMPLETIONS» transitions without a trigger in a row and is in state " + «names.stateField» + ": the automaton loops");
						}
					}
				}

				private boolean «names.completeOnceMethod»() {
					switch («names.stateField») {
						«FOR group : bySource(a, completions)»
							case «names.stateConstant(group.get(0).source)» -> {
								«FOR t : group»
									«transition(t, "return true;", false)»
								«ENDFOR»
							}
						«ENDFOR»
						default -> {
						}
					}
					return false;
				}
			«ENDIF»
		'''
	}

	private def String handler(ComponentType c, Automaton a, ArcPort p, boolean completions) {
		val triggered = a.transitions.filter[trigger == p].toList
		'''
			protected void «names.handler(p)»(«names.portTypeArgument(p)» «names.handlerParameter(p)») throws Exception {
				«IF completions»
					«names.startMethod»();
				«ENDIF»
				«IF !triggered.empty»
					switch («names.stateField») {
						«FOR group : bySource(a, triggered)»
							case «names.stateConstant(group.get(0).source)» -> {
								«FOR t : group»
									«transition(t, "return;", completions)»
								«ENDFOR»
							}
						«ENDFOR»
						default -> {
						}
					}
				«ENDIF»
				«names.unhandledMethod»("«names.runtimePortName(p)»", «names.handlerParameter(p)»);
			}
		'''
	}

	/** One transition: if enabled, its actions, the target state, then whatever follows it. */
	private def String transition(Transition t, String leave, boolean complete) {
		'''
			«IF t.guard !== null»if («java.expression(t.guard)») «ENDIF»{
				«FOR s : t.actions»
					«java.statement(s)»
				«ENDFOR»
				«names.stateField» = «names.stateEnum».«names.stateConstant(t.target)»;
				«IF complete»
					«names.completeMethod»();
				«ENDIF»
				«leave»
			}
		'''
	}

	/** Transitions grouped by source state, in model order. */
	private def List<List<Transition>> bySource(Automaton a, List<Transition> transitions) {
		a.states.map[s | transitions.filter[source == s].toList].filter[!empty].toList
	}
}
