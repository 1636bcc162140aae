package refarc;

import org.triad.refarc.*;

/* Behaviour is hand-written in org.triad.refarc.Planner (TOP pattern: generated PlannerTOP). */
component Planner(GoalPlanner goalPlanner) {
  port in PlanRequest request;
  port out StateRequest stateRequest;
  port in StateSnapshot state;
  port out PlanResult plan;
}
