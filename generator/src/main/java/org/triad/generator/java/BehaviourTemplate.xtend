package org.triad.generator.java

import java.util.LinkedHashSet
import java.util.List
import org.triad.dsl.triad.Action
import org.triad.dsl.triad.Actor
import org.triad.dsl.triad.DomainClass
import org.triad.dsl.triad.Parameter
import org.triad.dsl.triad.Property
import org.triad.dsl.typing.TriadType
import org.triad.dsl.typing.TriadTypeSystem

/**
 * The generated behaviours of RefArc's application-specific components: the state provider, which
 * observes the world through {@code IRobot} and {@code IWorld}, and the action executor, which
 * checks preconditions against the schema and calls the actions' methods through a typed
 * {@code ActionTable} (runtime library) built once from the schema.
 */
class BehaviourTemplate {
	val TriadNames names

	new(TriadNames names) {
		this.names = names
	}

	// ---- StateProvider -------------------------------------------------------------------------

	def String stateProvider(List<Actor> actors, List<DomainClass> classes) {
		val im = names.imports(names.basePackage, names.stateProviderClass)
		val body = stateProviderBody(actors, classes, im)
		unit(im, body)
	}

	private def String stateProviderBody(List<Actor> actors, List<DomainClass> classes, Imports im) {
		val list = im.ref("java.util.List")
		val domainObject = im.ref("org.triad.runtime.app.DomainObject")
		val state = im.ref("org.triad.runtime.app.State")
		val queried = actors.flatMap[properties].filter[enumerable]
		val candidateTypes = new LinkedHashSet<DomainClass>
		queried.forEach[parameters.map[TriadTypeSystem.typeOf(type)].filter[kind == TriadType.Kind.CLASS].forEach[candidateTypes.add(domainClass)]]
		'''
			/**
			 * Observes the world: the objects {@code «names.worldInterface»} lists, then every property of the robot and the
			 * world for every combination of arguments of the right types (Boolean properties that hold as facts, other
			 * properties with their values). Generated: do not edit.
			 */
			public class «names.stateProviderClass» implements «im.ref("org.triad.refarc.StateSource")» {
				«fields(im)»

				public «names.stateProviderClass»(«im.ref(names.qualifiedRobotInterface)» «names.robotField», «im.ref(names.qualifiedWorldInterface)» «names.worldField») {
					«fieldAssignments(im)»
				}

				@«im.ref("java.lang.Override")»
				public «state» currentState() {
					«state».Builder «names.stateBuilderVariable» = «state».builder();
					«list»<«domainObject»> «names.objectsVariable» = new «im.ref("java.util.ArrayList")»<>();
					«FOR c : classes»
						«objectsQuery(c, im)»
					«ENDFOR»
					«names.stateBuilderVariable».objects(«names.objectsVariable»);
					«FOR c : candidateTypes»
						«list»<«im.ref(names.qualifiedDomainClass(c))»> «names.candidatesVariable(c)» = «names.ofTypeMethod»(«names.objectsVariable», «im.ref(names.qualifiedDomainClass(c))».class);
					«ENDFOR»
					«FOR a : actors»
						«FOR p : a.properties»
							«propertyQuery(a, p, im)»
						«ENDFOR»
					«ENDFOR»
					return «names.stateBuilderVariable».build();
				}

				private static <T> «list»<T> «names.ofTypeMethod»(«list»<«domainObject»> objects, «im.ref("java.lang.Class")»<T> type) {
					«list»<T> result = new «im.ref("java.util.ArrayList")»<>();
					for («domainObject» o : objects) {
						if (type.isInstance(o)) {
							result.add(type.cast(o));
						}
					}
					return result;
				}
			}
		'''
	}

	/** A class of the domain: the objects of it that exist now. */
	def String objectsQuery(DomainClass c, Imports im) '''
		«names.objectsVariable».addAll(«im.ref("java.util.Objects")».requireNonNull(this.«names.worldField».«names.objectsMethod(c)»(), "«names.worldInterface».«names.objectsMethod(c)»() returned null"));
	'''

	/** A property: queried for every combination of candidate arguments. */
	def String propertyQuery(Actor a, Property p, Imports im) {
		if (!p.enumerable)
			return '''
				// «a.name».«p.name» is not observed: its «p.parameters.filter[!enumerable(type)].map[name].join(', ')» cannot be enumerated.
			'''
		val call = '''this.«actorField(a)».«names.propertyMethod(p)»(«p.parameters.indexed.map[names.argumentVariable(key)].join(', ')»)'''
		val atom = '''«im.ref("org.triad.runtime.app.Atom")».of(«JavaLiterals.string(a.name)», «JavaLiterals.string(p.name)»«FOR i : 0 ..< p.parameters.size», «names.argumentVariable(i)»«ENDFOR»)'''
		val record = if (TriadNames.isBoolean(p.type))
			'''
				if («call») {
					«names.stateBuilderVariable».fact(«atom»);
				}
			'''
		else
			'''
				«names.stateBuilderVariable».value(«atom», «call»);
			'''
		loops(p.parameters, 0, record, im)
	}

	private def String loops(List<Parameter> ps, int i, String inner, Imports im) {
		if (i == ps.size)
			return inner
		val t = TriadTypeSystem.typeOf(ps.get(i).type)
		val source = switch (t.kind) {
			case BOOLEAN: '''new boolean[] { false, true }'''
			case ENUM: '''«im.ref(names.qualifiedDomainClass(t.domainType))».values()'''
			default: names.candidatesVariable(t.domainClass)
		}
		'''
			for («im.ref(names.javaType(ps.get(i).type))» «names.argumentVariable(i)» : «source») {
				«loops(ps, i + 1, inner, im)»
			}
		'''
	}

	private def boolean enumerable(Property p) {
		p.parameters.forall[enumerable(type)]
	}

	private def boolean enumerable(org.triad.dsl.triad.TypeRef ref) {
		val k = TriadTypeSystem.typeOf(ref).kind
		k == TriadType.Kind.BOOLEAN || k == TriadType.Kind.CLASS || k == TriadType.Kind.ENUM
	}

	// ---- ActionExecutor ------------------------------------------------------------------------

	def String actionExecutor(List<Actor> actors) {
		val im = names.imports(names.basePackage, names.actionExecutorClass)
		val body = actionExecutorBody(actors, im)
		unit(im, body)
	}

	private def String actionExecutorBody(List<Actor> actors, Imports im) {
		val string = im.ref("java.lang.String")
		val object = im.ref("java.lang.Object")
		val groundAction = im.ref("org.triad.runtime.app.GroundAction")
		'''
			/**
			 * Executes actions: checks a precondition against a state with the application schema, and runs an action by
			 * calling its method on {@code «names.robotInterface»} or {@code «names.worldInterface»} through a table of typed
			 * method references built once. Generated: do not edit.
			 */
			public class «names.actionExecutorClass» implements «im.ref("org.triad.refarc.ActionRunner")» {
				«fields(im)»
				private final «im.ref("org.triad.runtime.schema.Transitions")» «names.transitionsField» = new «im.ref("org.triad.runtime.schema.Transitions")»(«im.ref(names.qualifiedSchemaClass)».«names.schemaField»);

				private final «im.ref("org.triad.runtime.schema.ActionTable")» «names.actionTableField»;

				public «names.actionExecutorClass»(«im.ref(names.qualifiedRobotInterface)» «names.robotField», «im.ref(names.qualifiedWorldInterface)» «names.worldField») {
					«fieldAssignments(im)»
					this.«names.actionTableField» = «im.ref("org.triad.runtime.schema.ActionTable")».builder(«im.ref(names.qualifiedSchemaClass)».«names.schemaField»)
						«FOR a : actors»
							«FOR act : a.actions»
								«actionEntry(a, act, im)»
							«ENDFOR»
						«ENDFOR»
						.build();
				}

				/** The first conjunct of the action's precondition that does not hold in {@code now}. */
				@«im.ref("java.lang.Override")»
				public «im.ref("java.util.Optional")»<«string»> violatedPrecondition(«groundAction» «names.actionParameter», «im.ref("org.triad.runtime.app.State")» «names.nowParameter») {
					«im.ref("org.triad.runtime.schema.ActionSchema")» «names.actionSchemaVariable» = this.«names.transitionsField».schemaOf(«names.actionParameter»);
					«im.ref("java.util.Map")»<«string», «object»> «names.bindingVariable» = this.«names.transitionsField».binding(«names.actionSchemaVariable», «names.actionParameter»);
					for («im.ref("org.triad.runtime.schema.Expr")» «names.conjunctVariable» : «im.ref("org.triad.runtime.schema.Exprs")».conjuncts(«names.actionSchemaVariable».pre())) {
						if (!this.«names.transitionsField».evaluator().holds(«names.conjunctVariable», «names.nowParameter», «names.bindingVariable»)) {
							return «im.ref("java.util.Optional")».of(«im.ref("org.triad.runtime.schema.Exprs")».show(«names.conjunctVariable»));
						}
					}
					return «im.ref("java.util.Optional")».empty();
				}

				/** Runs the action's method through the typed table built from the schema. */
				@«im.ref("java.lang.Override")»
				public boolean execute(«groundAction» «names.actionParameter») {
					return this.«names.actionTableField».execute(«names.actionParameter»);
				}

				@«im.ref("java.lang.Override")»
				public «im.ref("java.util.Optional")»<String> failureReason(«groundAction» «names.actionParameter») {
					«im.ref("java.lang.Object")» «names.actorVariable» = «FOR a : actors SEPARATOR ' : '»«names.actionParameter».actor().equals(«JavaLiterals.string(a.name)») ? this.«actorField(a)»«ENDFOR» : null;
					return «names.actorVariable» instanceof «im.ref("org.triad.runtime.app.FailureExplaining")» «names.explainingVariable» ? «names.explainingVariable».lastFailure() : «im.ref("java.util.Optional")».empty();
				}

				/** The failure with its cause (the building's congestion or a fault), from the actor that can tell. */
				@«im.ref("java.lang.Override")»
				public «im.ref("java.util.Optional")»<«im.ref("org.triad.runtime.app.Failure")»> failure(«groundAction» «names.actionParameter») {
					«im.ref("java.lang.Object")» «names.actorVariable» = «FOR a : actors SEPARATOR ' : '»«names.actionParameter».actor().equals(«JavaLiterals.string(a.name)») ? this.«actorField(a)»«ENDFOR» : null;
					return «names.actorVariable» instanceof «im.ref("org.triad.runtime.app.FailureExplaining")» «names.explainingVariable» ? «names.explainingVariable».lastFailureWithCause() : «im.ref("java.util.Optional")».empty();
				}
			}
		'''
	}

	/**
	 * An action's entry in the executor's table: a method reference with the parameters' Java types, so
	 * that the table and {@code IRobot}/{@code IWorld} agree at compile time (a lambda over typed
	 * arguments beyond six parameters).
	 */
	def String actionEntry(Actor a, Action act, Imports im) {
		val target = '''this.«actorField(a)»'''
		val head = '''«JavaLiterals.string(a.name)», «JavaLiterals.string(act.name)»'''
		if (act.parameters.size <= 6)
			'''.action(«head»«FOR p : act.parameters», «argumentClass(p, im)»«ENDFOR», «target»::«names.actionMethod(act)»)'''
		else
			'''.action(«head», «act.parameters.size», «names.argumentsVariable» -> «target».«names.actionMethod(act)»(«act.parameters.indexed.map[names.argumentsVariable + '.get(' + key + ', ' + argumentClass(value, im) + ')'].join(', ')»))'''
	}

	private def String argumentClass(Parameter p, Imports im) {
		val t = TriadTypeSystem.typeOf(p.type)
		switch (t.kind) {
			case BOOLEAN: '''«im.ref("java.lang.Boolean")».class'''
			case INT: '''«im.ref("java.lang.Integer")».class'''
			case DOUBLE: '''«im.ref("java.lang.Double")».class'''
			case STRING: '''«im.ref("java.lang.String")».class'''
			default: '''«im.ref(names.qualifiedDomainClass(t.domainType))».class'''
		}
	}

	// ---- shared --------------------------------------------------------------------------------

	private def String actorField(Actor a) {
		if (a.kind == org.triad.dsl.triad.ActorKind.ROBOT) names.robotField else names.worldField
	}

	private def String fields(Imports im) '''
		private final «im.ref(names.qualifiedRobotInterface)» «names.robotField»;
		private final «im.ref(names.qualifiedWorldInterface)» «names.worldField»;
	'''

	private def String fieldAssignments(Imports im) '''
		this.«names.robotField» = «im.ref("java.util.Objects")».requireNonNull(«names.robotField», "«names.robotField»");
		this.«names.worldField» = «im.ref("java.util.Objects")».requireNonNull(«names.worldField», "«names.worldField»");
	'''

	private def String unit(Imports im, String body) '''
		package «names.basePackage»;

		«im.declarations»

		«body»
	'''
}
