package org.triad.refarc;

import org.triad.runtime.app.TaskInstance;
import org.triad.runtime.component.ComposedComponent;
import org.triad.runtime.component.InPort;
import org.triad.runtime.component.OutPort;

/**
 * The reference architecture (Fig. 3 of the paper): tasks in, status out. Written the way the
 * architecture generator will emit it from {@code src/main/arc/refarc/RefArc.arc}: ports, one field
 * per subcomponent, and one method that makes the connections. Faults of any subcomponent go to the
 * Controller, which reports them on Status and fails the step they belong to.
 *
 * <p>To put a component between Planner and Controller (e.g. a {@link PlanVerifier}), use
 * {@link OpenRefArc}, which has the same parts but exposes that connection as two ports.
 */
public class RefArc extends ComposedComponent {
    public final InPort<TaskInstance> task = inPort("task", TaskInstance.class);
    public final OutPort<Status> status = outPort("status", Status.class);

    public final Controller controller;
    public final Planner planner;
    public final StateProvider stateProvider;
    public final ActionExecutor actionExecutor;

    public RefArc(StateSource stateSource, GoalPlanner goalPlanner, ActionRunner actionRunner) {
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
        connect(planner.plan, controller.plan);
        connect(controller.action, actionExecutor.action);
        connect(actionExecutor.stateRequest, stateProvider.executorQuery);
        connect(stateProvider.executorState, actionExecutor.state);
        connect(actionExecutor.result, controller.actionResult);
        connect(faults, controller.fault);
    }
}
