package org.triad.generator.java

import java.util.List
import org.triad.dsl.triad.Action
import org.triad.dsl.triad.Actor
import org.triad.dsl.triad.DomainClass
import org.triad.dsl.triad.Parameter
import org.triad.dsl.triad.Property

/**
 * The interfaces robotics experts implement: {@code IRobot} from the robot actor and {@code IWorld}
 * from the world actor and the domain's classes (paper, Sect. 4 and Fig. 4).
 */
class ActorInterfaceTemplate {
	val TriadNames names

	new(TriadNames names) {
		this.names = names
	}

	def String robotInterface(Actor robot) {
		val im = names.imports(names.basePackage, names.robotInterface)
		val body = '''
			/** The robot {@code «robot.name»}: implement it for a platform. Generated: do not edit. */
			public interface «names.robotInterface» {
				«members(robot, im)»
			}
		'''
		unit(im, body)
	}

	def String worldInterface(Actor world, List<DomainClass> classes) {
		val im = names.imports(names.basePackage, names.worldInterface)
		val body = '''
			/** The world {@code «world.name»} and the objects in it: implement it for an environment. Generated: do not edit. */
			public interface «names.worldInterface» {
				«members(world, im)»
				«FOR c : classes»

					«objectsMethod(c, classes, im)»
				«ENDFOR»
			}
		'''
		unit(im, body)
	}

	private def String unit(Imports im, String body) '''
		package «names.basePackage»;

		«im.declarations»

		«body»
	'''

	private def String members(Actor actor, Imports im) '''
		«FOR a : actor.actions SEPARATOR '\n'»
			«ModelJavadoc.action(actor, a)»
			«action(a, im)»
		«ENDFOR»
		«IF !actor.actions.empty && !actor.properties.empty»

		«ENDIF»
		«FOR p : actor.properties SEPARATOR '\n'»
			«ModelJavadoc.property(actor, p, names.worldInterface)»
			«property(p, im)»
		«ENDFOR»
	'''

	/** An action: executes it on the platform and tells whether it succeeded. */
	def String action(Action a, Imports im) '''
		boolean «names.actionMethod(a)»(«parameters(a.parameters, im)»);
	'''

	/** A property: a Boolean property tells whether it holds, another one its current value. */
	def String property(Property p, Imports im) '''
		«im.ref(names.javaType(p.type))» «names.propertyMethod(p)»(«parameters(p.parameters, im)»);
	'''

	/** The objects of a class that exist now (objects of its subclasses may be included; each is counted once). */
	def String objectsMethod(DomainClass c, List<DomainClass> classes, Imports im) '''
		«ModelJavadoc.objects(c, classes, [d | names.objectsMethod(d)])»
		«im.ref("java.util.List")»<«im.ref(names.qualifiedDomainClass(c))»> «names.objectsMethod(c)»();
	'''

	private def String parameters(List<Parameter> ps, Imports im) {
		ps.map[im.ref(names.javaType(type)) + " " + names.parameter(it)].join(", ")
	}
}
