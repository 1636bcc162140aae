package refarc;

import org.triad.runtime.app.TaskInstance;
import org.triad.refarc.*;

/*
 * RefArc with the Planner-to-Controller connection exposed as two ports: the Planner's results
 * leave on proposedPlan and the Controller takes plans from plan. An application puts a component
 * (e.g. a PlanVerifier) in between purely by connecting ports:
 *   core.proposedPlan -> verifier.proposed;
 *   verifier.verified -> core.plan;
 * Whatever is inserted must answer every PlanResult with one PlanResult of the same request id,
 * otherwise the Controller waits for it. Java form (generated): org.triad.refarc.OpenRefArc.
 */
component OpenRefArc(StateSource stateSource, GoalPlanner goalPlanner, ActionRunner actionRunner) {
  port in TaskInstance task;
  port out Status status;
  port out PlanResult proposedPlan;
  port in PlanResult plan;

  Controller controller;
  Planner planner(goalPlanner);
  StateProvider stateProvider(stateSource);
  ActionExecutor actionExecutor(actionRunner);

  task -> controller.task;
  controller.status -> status;
  controller.planRequest -> planner.request;
  planner.stateRequest -> stateProvider.plannerQuery;
  stateProvider.plannerState -> planner.state;
  planner.plan -> proposedPlan;
  plan -> controller.plan;
  controller.action -> actionExecutor.action;
  actionExecutor.stateRequest -> stateProvider.executorQuery;
  stateProvider.executorState -> actionExecutor.state;
  actionExecutor.result -> controller.actionResult;
  faults -> controller.fault;
}
