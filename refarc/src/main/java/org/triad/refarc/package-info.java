/**
 * The domain-independent reference architecture of the paper (Fig. 3, Sect. 5), built on the
 * component runtime.
 *
 * <p>{@link org.triad.refarc.RefArc} has a {@code task} in port and a {@code status} out port and
 * consists of {@link org.triad.refarc.Controller}, {@link org.triad.refarc.Planner},
 * {@link org.triad.refarc.StateProvider} and {@link org.triad.refarc.ActionExecutor}. The
 * application-specific parts are back-ends passed in as configuration: {@link org.triad.refarc.StateSource},
 * {@link org.triad.refarc.GoalPlanner} and {@link org.triad.refarc.ActionRunner}, implemented by
 * generated code.
 *
 * <p>Applications extend the architecture by connecting ports: {@link org.triad.refarc.RemoteOperator}
 * listens to Status; {@link org.triad.refarc.PlanVerifier} goes between Planner and Controller of
 * {@link org.triad.refarc.OpenRefArc}, the variant that exposes that connection as ports.
 * {@link org.triad.refarc.RefArcRunner} runs one task synchronously for tests and the CLI.
 *
 * <p>The architecture generator emits, from the models in {@code src/main/arc}, the {@code *TOP}
 * classes (MontiArc's TOP pattern) that the hand-written components extend: ports and one handler per
 * in port, and for the Controller its whole behaviour, the automaton of {@code Controller.arc}; and the
 * compositions {@code RefArc} and {@code OpenRefArc}. The build ({@code xtext-maven-plugin}) puts them
 * in {@code target/generated-sources/arc}.
 */
package org.triad.refarc;
