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
 * classes (ports and one handler per in port, MontiArc's TOP pattern) that the hand-written
 * components extend, and the compositions {@code RefArc} and {@code OpenRefArc}; the build puts
 * them in {@code target/generated-sources/arc}.
 */
package org.triad.refarc;
