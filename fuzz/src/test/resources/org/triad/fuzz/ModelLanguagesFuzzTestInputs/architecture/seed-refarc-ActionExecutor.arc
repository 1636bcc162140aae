package refarc;

import org.triad.refarc.*;

/* Behaviour is hand-written in org.triad.refarc.ActionExecutor (TOP pattern: generated ActionExecutorTOP). */
component ActionExecutor(ActionRunner actionRunner) {
  port in ActionRequest action;
  port out StateRequest stateRequest;
  port in StateSnapshot state;
  port out ActionResult result;
}
