package refarc;

import org.triad.runtime.app.TaskInstance;
import org.triad.runtime.component.ComponentFault;
import org.triad.refarc.*;

/* Behaviour is hand-written in org.triad.refarc.Controller (TOP pattern: generated ControllerTOP). */
component Controller {
  port in TaskInstance task;
  port in PlanResult plan;
  port in ActionResult actionResult;
  port in ComponentFault fault;
  port out PlanRequest planRequest;
  port out ActionRequest action;
  port out Status status;
}
