package org.triad.generator.java

import org.triad.dsl.triad.Attribute
import org.triad.dsl.triad.DomainClass
import org.triad.dsl.triad.Enumeration

/** The Java class of a domain class, and the Java enum of an enumeration, of the class diagram. */
class DomainTypeTemplate {
	val TriadNames names

	new(TriadNames names) {
		this.names = names
	}

	def String domainClass(DomainClass c) {
		val im = names.imports(names.domainPackage, names.domainClass(c))
		val body = classBody(c, im)
		'''
			package «names.domainPackage»;

			«im.declarations»

			«body»
		'''
	}

	private def String classBody(DomainClass c, Imports im) {
		val superClass = if (c.superType === null) im.ref("org.triad.runtime.app.DomainObject") else im.ref(names.qualifiedDomainClass(c.superType))
		val string = im.ref("java.lang.String")
		'''
			/** Class {@code «c.name»} of class diagram {@code «(c.eContainer as org.triad.dsl.triad.ClassDiagram).name»}. Generated: extend, do not edit. */
			public «IF c.abstract»abstract «ENDIF»class «names.domainClass(c)» extends «superClass» {
				«FOR a : c.attributes»
					«attributeField(a, im)»
				«ENDFOR»

				«IF c.abstract»protected«ELSE»public«ENDIF» «names.domainClass(c)»(«string» «names.objectNameParameter») {
					super(«names.objectNameParameter»);
				}
				«IF !c.abstract»

					@«im.ref("java.lang.Override")»
					public «string» «names.typeNameMethod»() {
						return "«c.name»";
					}
				«ENDIF»
				«FOR a : c.attributes»

					«attributeAccessors(a, im)»
				«ENDFOR»
				«IF !c.attributes.empty»

					«attributeByName(c, im)»
				«ENDIF»
			}
		'''
	}

	private def String attributeField(Attribute a, Imports im) '''
		private «im.ref(names.javaType(a.type))» «names.field(a)»;
	'''

	private def String attributeAccessors(Attribute a, Imports im) '''
		«ModelJavadoc.attribute(a.eContainer as DomainClass, a)»
		public «im.ref(names.javaType(a.type))» «names.getter(a)»() {
			return this.«names.field(a)»;
		}

		public void «names.setter(a)»(«im.ref(names.javaType(a.type))» value) {
			this.«names.field(a)» = value;
		}
	'''

	/** What the runtime reads when a model reads an attribute ({@code i.weight}). */
	private def String attributeByName(DomainClass c, Imports im) '''
		@«im.ref("java.lang.Override")»
		public «im.ref("java.lang.Object")» attribute(«im.ref("java.lang.String")» attribute) {
			return switch (attribute) {
				«FOR a : c.attributes»
					case «JavaLiterals.string(a.name)» -> «names.getter(a)»();
				«ENDFOR»
				default -> super.attribute(attribute);
			};
		}
	'''

	def String enumeration(Enumeration e) '''
		package «names.domainPackage»;

		/** Enumeration {@code «e.name»} of the class diagram. Generated: do not edit. */
		public enum «names.domainClass(e)» {
			«FOR l : e.literals SEPARATOR ','»
				«names.enumConstant(l)»
			«ENDFOR»
		}
	'''
}
