package examples.hospital;

import org.triad.runtime.app.TaskInstance;
import org.triad.refarc.*;
import refarc.OpenRefArc;
import refarc.PlanVerifier;
import refarc.RemoteOperator;

/*
 * The hospital application's architecture: RefArc, extended without touching it. A plan verifier
 * sits between RefArc's Planner and Controller and rejects plans the plan check refutes; a remote
 * operator takes the remote-operation requests from Status. One component and connectors each.
 */
component VerifiedHospital(StateSource stateSource, GoalPlanner goalPlanner, ActionRunner actionRunner, PlanCheck check) {
  port in TaskInstance request;
  port out Status status;

  OpenRefArc core(stateSource, goalPlanner, actionRunner);
  PlanVerifier verifier(check);
  RemoteOperator operator;

  request -> core.task;
  core.status -> status, operator.status;
  core.proposedPlan -> verifier.proposed;
  verifier.verified -> core.plan;
}
