package org.triad.refarc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.triad.refarc.Corridor.Planning;
import org.triad.refarc.Corridor.ScriptedPlanner;
import org.triad.refarc.Corridor.Task;
import org.triad.refarc.Corridor.World;
import org.triad.runtime.app.TaskInstance;
import org.triad.runtime.component.ComposedComponent;
import org.triad.runtime.component.DeterministicScheduler;
import org.triad.runtime.component.InPort;
import org.triad.runtime.component.OutPort;
import org.triad.runtime.component.Scheduler;

/** Applications extend RefArc purely by connecting ports, as generated from their .arc models. */
class ExtensionTest {

    /** {@code HospitalApp { RefArc core; RemoteOperator operator; request -> core.task; core.status -> status, operator.status; }} */
    static final class HospitalApp extends ComposedComponent {
        final InPort<TaskInstance> request = inPort("request", TaskInstance.class);
        final OutPort<Status> status = outPort("status", Status.class);
        final RefArc core;
        final RemoteOperator operator;

        HospitalApp(World world, GoalPlanner planner, List<Status.RemoteOperationRequested> handled) {
            core = subcomponent("core", new RefArc(world, planner, world));
            operator = subcomponent("operator", new RemoteOperator(handled::add));
            connectPorts();
        }

        private void connectPorts() {
            connect(request, core.task);
            connect(core.status, status, operator.status);
        }
    }

    /**
     * {@code VerifiedHospitalApp { OpenRefArc core; PlanVerifier verifier; RemoteOperator operator;
     * request -> core.task; core.status -> status, operator.status;
     * core.proposedPlan -> verifier.proposed; verifier.verified -> core.plan; }}
     */
    static final class VerifiedHospitalApp extends ComposedComponent {
        final InPort<TaskInstance> request = inPort("request", TaskInstance.class);
        final OutPort<Status> status = outPort("status", Status.class);
        final OpenRefArc core;
        final PlanVerifier verifier;
        final RemoteOperator operator;

        VerifiedHospitalApp(World world, GoalPlanner planner, PlanCheck check) {
            core = subcomponent("core", new OpenRefArc(world, planner, world));
            verifier = subcomponent("verifier", new PlanVerifier(check));
            operator = subcomponent("operator", new RemoteOperator());
            connectPorts();
        }

        private void connectPorts() {
            connect(request, core.task);
            connect(core.status, status, operator.status);
            connect(core.proposedPlan, verifier.proposed);
            connect(verifier.verified, core.plan);
        }
    }

    private static List<String> run(ComposedComponent app, InPort<TaskInstance> request, OutPort<Status> status, Task task) {
        List<String> log = new ArrayList<>();
        status.observe(s -> log.add(s.toString()));
        DeterministicScheduler s = Scheduler.deterministic();
        s.deploy(app);
        s.send(request, task);
        s.runToCompletion();
        assertTrue(s.unhandledFaults().isEmpty(), () -> "unhandled " + s.unhandledFaults());
        return log;
    }

    @Test
    void theRemoteOperatorReceivesRemoteOperationRequestsFromStatus() {
        World world = new World("a");
        List<Status.RemoteOperationRequested> handled = new ArrayList<>();
        HospitalApp app = new HospitalApp(world, ScriptedPlanner.thenAlways(Planning.fail("stairs")), handled);
        List<String> log = run(app, app.request, app.status, Task.goTo("c"));
        assertEquals("remote operation requested for task GoTo(c) at goal IsAt(c): planning failed: stairs", log.get(log.size() - 1));
        assertEquals(1, handled.size());
        assertEquals(handled, app.operator.requests());
        assertEquals("planning failed: stairs", handled.get(0).reason());
    }

    @Test
    void theRemoteOperatorStaysQuietWhileTasksSucceed() {
        World world = new World("a");
        List<Status.RemoteOperationRequested> handled = new ArrayList<>();
        HospitalApp app = new HospitalApp(world, new ScriptedPlanner(), handled);
        List<String> log = run(app, app.request, app.status, Task.goTo("c"));
        assertEquals("task GoTo(c) completed", log.get(log.size() - 1));
        assertEquals(List.of(), handled);
    }

    @Test
    void aVerifierLetsValidPlansThrough() {
        World world = new World("a");
        ScriptedPlanner planner = new ScriptedPlanner();
        VerifiedHospitalApp app = new VerifiedHospitalApp(world, planner, Corridor.SIMULATION);
        List<String> log = run(app, app.request, app.status, Task.goTo("a", "c"));
        assertEquals(List.of(
                "task GoTo(a, c) started",
                "goal IsAt(a) already satisfied",
                "plan for IsAt(c): robot.move(a, b), robot.move(b, c)",
                "action 1/2 robot.move(a, b) started",
                "action robot.move(a, b) succeeded",
                "action 2/2 robot.move(b, c) started",
                "action robot.move(b, c) succeeded",
                "goal IsAt(c) satisfied",
                "task GoTo(a, c) completed"), log);
        assertEquals(1, planner.calls());
    }

    @Test
    void aRefutedPlanMakesTheControllerReplan() {
        World world = new World("a");
        ScriptedPlanner planner = new ScriptedPlanner(Planning.JUMP);
        VerifiedHospitalApp app = new VerifiedHospitalApp(world, planner, Corridor.SIMULATION);
        List<String> log = run(app, app.request, app.status, Task.goTo("c"));
        assertEquals(List.of(
                "task GoTo(c) started",
                "replanning IsAt(c) (1 of 3): planning failed: plan refuted: robot.move(a, c): a and c are not adjacent",
                "plan for IsAt(c): robot.move(a, b), robot.move(b, c)"), log.subList(0, 3));
        assertEquals("task GoTo(c) completed", log.get(log.size() - 1));
        assertEquals(2, planner.calls());
        assertEquals(List.of("robot.move(a, b)", "robot.move(b, c)"), world.executed(), "the corrupted plan never ran");
    }

    @Test
    void fourRefutationsInARowAbortTheTask() {
        World world = new World("a");
        ScriptedPlanner planner = ScriptedPlanner.thenAlways(Planning.JUMP);
        VerifiedHospitalApp app = new VerifiedHospitalApp(world, planner, Corridor.SIMULATION);
        List<String> log = run(app, app.request, app.status, Task.goTo("c"));
        String reason = "planning failed: plan refuted: robot.move(a, c): a and c are not adjacent";
        assertEquals(List.of(
                "task GoTo(c) started",
                "replanning IsAt(c) (1 of 3): " + reason,
                "replanning IsAt(c) (2 of 3): " + reason,
                "replanning IsAt(c) (3 of 3): " + reason,
                "task GoTo(c) aborted at goal IsAt(c): " + reason,
                "remote operation requested for task GoTo(c) at goal IsAt(c): " + reason), log);
        assertEquals(4, planner.calls());
        assertEquals(List.of(), world.executed());
        assertEquals(1, app.operator.requests().size());
    }

    @Test
    void aPlanCheckThatThrowsRefutesThePlanInsteadOfStallingTheController() {
        World world = new World("a");
        PlanCheck broken = (g, from, p) -> {
            throw new UnsupportedOperationException("no model");
        };
        VerifiedHospitalApp app = new VerifiedHospitalApp(world, new ScriptedPlanner(), broken);
        List<String> log = run(app, app.request, app.status, Task.goTo("b"));
        assertEquals("replanning IsAt(b) (1 of 3): planning failed: plan refuted: the plan check threw UnsupportedOperationException: no model",
                log.get(1));
        assertEquals("remote operation requested for task GoTo(b) at goal IsAt(b): planning failed: plan refuted: the plan check threw UnsupportedOperationException: no model",
                log.get(log.size() - 1));
    }

    @Test
    void faultsInsideTheCoreStayInsideTheCore() {
        World world = new World("a").failFetch(1);
        List<Status.RemoteOperationRequested> handled = new ArrayList<>();
        HospitalApp app = new HospitalApp(world, new ScriptedPlanner(), handled);
        List<String> log = run(app, app.request, app.status, Task.goTo("b"));
        assertEquals("component fault in hospitalApp.core.stateProvider at plannerQuery handling state request #1: IllegalStateException: sensor offline",
                log.get(1));
        assertEquals("task GoTo(b) completed", log.get(log.size() - 1));
    }

    /** A faulty extension that forwards every plan result twice. */
    static final class Stutter extends PlanVerifierTOP {
        @Override
        protected void onProposed(PlanResult message) {
            verified.send(message);
            verified.send(message);
        }
    }

    static final class StutteringApp extends ComposedComponent {
        final InPort<TaskInstance> request = inPort("request", TaskInstance.class);
        final OutPort<Status> status = outPort("status", Status.class);
        final OpenRefArc core;
        final Stutter stutter = subcomponent("stutter", new Stutter());

        StutteringApp(World world) {
            core = subcomponent("core", new OpenRefArc(world, new ScriptedPlanner(), world));
            connect(request, core.task);
            connect(core.status, status);
            connect(core.proposedPlan, stutter.proposed);
            connect(stutter.verified, core.plan);
        }
    }

    @Test
    void anUnexpectedReplyIsReportedOnStatusAndDoesNotDerailTheTask() {
        World world = new World("a");
        StutteringApp app = new StutteringApp(world);
        List<String> log = run(app, app.request, app.status, Task.goTo("b"));
        assertEquals(List.of(
                "task GoTo(b) started",
                "plan for IsAt(b): robot.move(a, b)",
                "action 1/1 robot.move(a, b) started",
                "component fault in stutteringApp.core.controller at plan handling plan result #1 for IsAt(b): 1 action:"
                        + " IllegalStateException: unexpected plan result #1 for IsAt(b): 1 action while executing and waiting for request #2",
                "action robot.move(a, b) succeeded",
                "goal IsAt(b) satisfied",
                "task GoTo(b) completed"), log);
        assertEquals(List.of("robot.move(a, b)"), world.executed());
    }
}
