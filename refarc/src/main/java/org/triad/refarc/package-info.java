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
 * <p>The {@code *TOP} classes are the parts the architecture generator will emit from the models in
 * {@code src/main/arc} (MontiArc's TOP pattern); until it exists they are written by hand and
 * {@code ArcModelConsistencyTest} keeps them in step with the models.
 */
package org.triad.refarc;
