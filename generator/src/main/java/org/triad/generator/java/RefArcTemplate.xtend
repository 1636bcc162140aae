package org.triad.generator.java

/**
 * The application's entry point for running tasks from Java: RefArc around the robotics expert's
 * {@code IRobot} and {@code IWorld}, through the generated StateProvider and ActionExecutor and the
 * runtime's {@code TaskRunner}.
 */
class RefArcTemplate {
	val TriadNames names

	new(TriadNames names) {
		this.names = names
	}

	def String refArcClass() {
		val im = names.imports(names.basePackage, names.refArcClass)
		val runner = im.ref("org.triad.refarc.TaskRunner")
		val body = '''
			/**
			 * RefArc for application {@code «names.schemaClass»}: {@code «names.refArcClass».of(robot, world).run("Task", "object", ...)}
			 * runs a task by name, its object arguments by name among those the world lists, and returns its
			 * {@code RefArcRun} (outcome and every Status); {@code onStatus(observer)} sees Status as it happens.
			 * Generated: do not edit.
			 */
			public final class «names.refArcClass» {
				private «names.refArcClass»() {
				}

				/** RefArc observing and driving this robot and world, planning with Triad's engine. */
				public static «runner» of(«names.robotInterface» robot, «names.worldInterface» world) {
					return new «runner»(«names.schemaClass».«names.schemaField», new «names.stateProviderClass»(robot, world),
							new «names.actionExecutorClass»(robot, world));
				}
			}
		'''
		'''
			package «names.basePackage»;

			«im.declarations»

			«body»
		'''
	}
}
