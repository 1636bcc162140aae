package org.triad.refarc;

import org.triad.runtime.app.TaskInstance;
import org.triad.runtime.component.AtomicComponent;
import org.triad.runtime.component.ComponentFault;
import org.triad.runtime.component.InPort;
import org.triad.runtime.component.OutPort;

/**
 * Interface of the Controller as the architecture generator will emit it from
 * {@code src/main/arc/refarc/Controller.arc} (hand-written until that generator exists): ports, and
 * one handler method per in port for the hand-written {@link Controller} (MontiArc's TOP pattern).
 */
public abstract class ControllerTOP extends AtomicComponent {
    public final InPort<TaskInstance> task = inPort("task", TaskInstance.class);
    public final InPort<PlanResult> plan = inPort("plan", PlanResult.class);
    public final InPort<ActionResult> actionResult = inPort("actionResult", ActionResult.class);
    public final InPort<ComponentFault> fault = inPort("fault", ComponentFault.class);
    public final OutPort<PlanRequest> planRequest = outPort("planRequest", PlanRequest.class);
    public final OutPort<ActionRequest> action = outPort("action", ActionRequest.class);
    public final OutPort<Status> status = outPort("status", Status.class);

    protected ControllerTOP() {
        on(task, this::onTask);
        on(plan, this::onPlan);
        on(actionResult, this::onActionResult);
        on(fault, this::onFault);
    }

    protected abstract void onTask(TaskInstance message) throws Exception;

    protected abstract void onPlan(PlanResult message) throws Exception;

    protected abstract void onActionResult(ActionResult message) throws Exception;

    protected abstract void onFault(ComponentFault message) throws Exception;
}
