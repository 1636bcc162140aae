package refarc;

import org.triad.runtime.app.TaskInstance;
import org.triad.refarc.*;

/*
 * The reference architecture (Fig. 3 of the paper): tasks in, status out. The Java class
 * org.triad.refarc.RefArc is generated from this model.
 *
 * `faults` is the runtime-fed in port every composed component has: faults of subcomponents go to
 * the Controller, which reports them on Status and fails the step they belong to.
 *
 * To put a component between Planner and Controller (e.g. a PlanVerifier), use OpenRefArc, which
 * has the same parts but exposes that connection as two ports.
 */
component RefArc(StateSource stateSource, GoalPlanner goalPlanner, ActionRunner actionRunner) {
  port in TaskInstance task;
  port out Status status;

  Controller controller;
  Planner planner(goalPlanner);
  StateProvider stateProvider(stateSource);
  ActionExecutor actionExecutor(actionRunner);

  task -> controller.task;
  controller.status -> status;
  controller.planRequest -> planner.request;
  planner.stateRequest -> stateProvider.plannerQuery;
  stateProvider.plannerState -> planner.state;
  planner.plan -> controller.plan;
  controller.action -> actionExecutor.action;
  actionExecutor.stateRequest -> stateProvider.executorQuery;
  stateProvider.executorState -> actionExecutor.state;
  actionExecutor.result -> controller.actionResult;
  faults -> controller.fault;
}
