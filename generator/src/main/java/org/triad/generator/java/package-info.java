/**
 * The Java code generator (paper, Sect. 4). Xtend templates, one per artifact kind
 * ({@link org.triad.generator.java.DomainTypeTemplate}, {@link org.triad.generator.java.ActorInterfaceTemplate},
 * {@link org.triad.generator.java.GoalTemplate}, {@link org.triad.generator.java.TaskTemplate},
 * {@link org.triad.generator.java.SchemaTemplate}, {@link org.triad.generator.java.BehaviourTemplate}), take every
 * generated name from {@link org.triad.generator.java.TriadNames}. Entry points:
 * {@link org.triad.generator.java.TriadJavaGenerator#generate} (and its {@code main}) and, for Xtext builders such as
 * the {@code xtext-maven-plugin}, {@link org.triad.generator.java.TriadJavaGeneratorSetup}, which binds
 * {@link org.triad.generator.java.TriadApplicationGenerator} to the class-diagram language.
 * <p>
 * For an application with base package {@code P} (default {@code generated.<application name>}):
 * {@code P.domain} classes and enums, {@code P.IRobot}, {@code P.IWorld}, {@code P.goals}, {@code P.tasks},
 * {@code P.<App>Schema}, {@code P.<App>StateProvider} (a {@code refarc.StateSource}) and
 * {@code P.<App>ActionExecutor} (a {@code refarc.ActionRunner}).
 */
package org.triad.generator.java;
