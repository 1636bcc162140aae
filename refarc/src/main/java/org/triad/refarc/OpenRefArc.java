package org.triad.refarc;

import org.triad.runtime.app.TaskInstance;
import org.triad.runtime.component.ComposedComponent;
import org.triad.runtime.component.InPort;
import org.triad.runtime.component.OutPort;

/**
 * {@link RefArc} with its Planner-to-Controller connection opened: the Planner's results leave on
 * {@link #proposedPlan} and the Controller takes plans from {@link #plan}. An application inserts a
 * component between them purely by connecting ports, e.g. (from an .arc model)
 * {@code core.proposedPlan -> verifier.proposed; verifier.verified -> core.plan;}. Whatever is
 * inserted must answer every {@link PlanResult} with one {@link PlanResult} of the same request id,
 * otherwise the Controller waits for it. Generated from {@code src/main/arc/refarc/OpenRefArc.arc}.
 */
public class OpenRefArc extends ComposedComponent {
    public final InPort<TaskInstance> task = inPort("task", TaskInstance.class);
    public final OutPort<Status> status = outPort("status", Status.class);
    public final OutPort<PlanResult> proposedPlan = outPort("proposedPlan", PlanResult.class);
    public final InPort<PlanResult> plan = inPort("plan", PlanResult.class);

    public final Controller controller;
    public final Planner planner;
    public final StateProvider stateProvider;
    public final ActionExecutor actionExecutor;

    public OpenRefArc(StateSource stateSource, GoalPlanner goalPlanner, ActionRunner actionRunner) {
        controller = subcomponent("controller", new Controller());
        planner = subcomponent("planner", new Planner(goalPlanner));
        stateProvider = subcomponent("stateProvider", new StateProvider(stateSource));
        actionExecutor = subcomponent("actionExecutor", new ActionExecutor(actionRunner));
        connectPorts();
    }

    private void connectPorts() {
        connect(task, controller.task);
        connect(controller.status, status);
        connect(controller.planRequest, planner.request);
        connect(planner.stateRequest, stateProvider.plannerQuery);
        connect(stateProvider.plannerState, planner.state);
        connect(planner.plan, proposedPlan);
        connect(plan, controller.plan);
        connect(controller.action, actionExecutor.action);
        connect(actionExecutor.stateRequest, stateProvider.executorQuery);
        connect(stateProvider.executorState, actionExecutor.state);
        connect(actionExecutor.result, controller.actionResult);
        connect(faults, controller.fault);
    }
}
