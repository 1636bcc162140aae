package org.triad.runtime.component;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.triad.runtime.component.TestComponents.Deaf;
import org.triad.runtime.component.TestComponents.FaultCollector;
import org.triad.runtime.component.TestComponents.Mapper;
import org.triad.runtime.component.TestComponents.Sink;
import org.triad.runtime.component.TestComponents.Worker;

class DeterministicSchedulerTest {

    /** in -> inner(a -> b) -> out, a second branch a -> sink, faults routed to a collector when asked. */
    static final class Nested extends ComposedComponent {
        final InPort<Integer> in = inPort("in", Integer.class);
        final OutPort<Integer> out = outPort("out", Integer.class);
        final Inner inner = subcomponent("inner", new Inner());
        final FaultCollector collector = subcomponent("collector", new FaultCollector());

        Nested(boolean routeFaults) {
            connect(in, inner.in);
            connect(inner.out, out);
            if (routeFaults) {
                connect(faults, collector.in);
            }
        }
    }

    static final class Inner extends ComposedComponent {
        final InPort<Integer> in = inPort("in", Integer.class);
        final OutPort<Integer> out = outPort("out", Integer.class);
        final Mapper a = subcomponent("a", new Mapper(x -> 100 / x));
        final Mapper b = subcomponent("b", new Mapper(x -> x + 1));
        final Sink<Integer> sink = subcomponent("sink", new Sink<>(Integer.class, 13));

        Inner() {
            connect(in, a.in);
            connect(a.out, b.in, sink.in);
            connect(b.out, out);
        }
    }

    @Test
    void messagesFlowThroughNestedCompositionsInFifoOrder() {
        Nested n = new Nested(false);
        DeterministicScheduler s = Scheduler.deterministic();
        List<Integer> out = new ArrayList<>();
        n.out.observe(out::add);
        s.deploy(n);
        s.send(n.in, 1);
        s.send(n.in, 2);
        s.send(n.in, 4);
        assertEquals(9, s.runUntilIdle());
        assertEquals(List.of(101, 51, 26), out);
        assertEquals(List.of(100, 50, 25), n.inner.sink.received);
        assertEquals("nested.inner.a", n.inner.a.path());
        assertEquals(0, s.runUntilIdle());
    }

    @Test
    void aThrowingHandlerBecomesAFaultRoutedToTheNearestConnectedFaultsPort() {
        Nested n = new Nested(true);
        DeterministicScheduler s = Scheduler.deterministic();
        List<Integer> out = new ArrayList<>();
        n.out.observe(out::add);
        s.deploy(n);
        s.send(n.in, 0); // 100 / 0 throws in inner.a
        s.send(n.in, 10);
        s.runUntilIdle();
        assertEquals(List.of(11), out, "the architecture keeps working after the fault");
        assertEquals(1, n.collector.faults.size());
        ComponentFault f = n.collector.faults.get(0);
        assertEquals("nested.inner.a", f.componentPath());
        assertEquals("in", f.port());
        assertEquals(0, f.message());
        assertInstanceOf(ArithmeticException.class, f.cause());
        assertTrue(f.toString().contains("fault in nested.inner.a at in handling 0: ArithmeticException"), f.toString());
        assertTrue(s.unhandledFaults().isEmpty());
    }

    @Test
    void withoutARouteFaultsGoToTheSchedulerListener() {
        Nested n = new Nested(false);
        DeterministicScheduler s = Scheduler.deterministic();
        List<ComponentFault> heard = new ArrayList<>();
        s.onUnhandledFault(heard::add);
        s.deploy(n);
        s.send(n.in, 0);
        s.runUntilIdle();
        assertEquals(1, heard.size());
        assertEquals("nested.inner.a", heard.get(0).componentPath());
    }

    @Test
    void withoutAnyListenerFaultsAreKeptNotDropped() {
        Nested n = new Nested(false);
        DeterministicScheduler s = Scheduler.deterministic();
        s.deploy(n);
        s.send(n.in, 0);
        s.runUntilIdle();
        assertEquals(1, s.unhandledFaults().size());
    }

    @Test
    void aMessageAtAnInPortWithoutHandlerIsAFault() {
        Deaf deaf = new Deaf();
        DeterministicScheduler s = Scheduler.deterministic();
        s.deploy(deaf);
        s.send(deaf.in, "hello");
        s.runUntilIdle();
        ComponentFault f = s.unhandledFaults().get(0);
        assertEquals("deaf", f.componentPath());
        assertEquals("in", f.port());
        assertEquals("hello", f.message());
        assertTrue(f.cause().getMessage().contains("no handler for in port deaf.in"), f.cause().getMessage());
    }

    static final class Unwired extends ComposedComponent {
        final InPort<String> in = inPort("in", String.class);
        final OutPort<String> out = outPort("out", String.class);
    }

    @Test
    void aComposedInPortWithoutInnerConnectionIsAFaultButAnUnconnectedOutPortIsFine() {
        Unwired u = new Unwired();
        DeterministicScheduler s = Scheduler.deterministic();
        s.deploy(u);
        u.out.send("nobody listens");
        assertTrue(s.unhandledFaults().isEmpty());
        s.send(u.in, "lost?");
        assertEquals(1, s.unhandledFaults().size());
        assertTrue(s.unhandledFaults().get(0).cause().getMessage().contains("not connected to any subcomponent"));
    }

    @Test
    void aFaultWhileHandlingAFaultGoesToTheListenerInsteadOfLooping() {
        Nested n = new Nested(true);
        n.collector.throwOnFault = true;
        DeterministicScheduler s = Scheduler.deterministic();
        s.deploy(n);
        s.send(n.in, 0);
        s.runUntilIdle();
        assertEquals(1, n.collector.faults.size());
        assertEquals(1, s.unhandledFaults().size());
        assertEquals("nested.collector", s.unhandledFaults().get(0).componentPath());
    }

    static final class WorkerBox extends ComposedComponent {
        final InPort<String> request = inPort("request", String.class);
        final InPort<String> ping = inPort("ping", String.class);
        final OutPort<String> done = outPort("done", String.class);
        final Worker worker = subcomponent("worker", new Worker(r -> () -> {
            if (r.equals("bad")) {
                throw new IllegalArgumentException("cannot do " + r);
            }
            return r.toUpperCase();
        }));
        final FaultCollector collector = subcomponent("collector", new FaultCollector());

        WorkerBox() {
            connect(request, worker.request);
            connect(ping, worker.ping);
            connect(worker.done, done);
            connect(faults, collector.in);
        }
    }

    @Test
    void activitiesWaitForTheTestAndDeliverTheirResultAsAMessage() {
        WorkerBox box = new WorkerBox();
        DeterministicScheduler s = Scheduler.deterministic();
        List<String> done = new ArrayList<>();
        box.done.observe(done::add);
        s.deploy(box);
        s.send(box.request, "fetch");
        s.runUntilIdle();
        assertEquals(List.of("workerBox.worker activity work on fetch"), s.pendingActivities());
        s.send(box.ping, "1");
        s.runUntilIdle();
        assertEquals(List.of("start fetch", "ping 1"), box.worker.log, "the component handles messages while its activity is pending");
        assertTrue(done.isEmpty());
        assertTrue(s.runNextActivity());
        assertEquals(List.of("start fetch", "ping 1"), box.worker.log, "the result is a queued message, not a callback on the worker");
        s.runUntilIdle();
        assertEquals(List.of("FETCH"), done);
        assertFalse(s.runNextActivity());
    }

    @Test
    void aThrowingActivityBecomesAFaultNamingItsSubject() {
        WorkerBox box = new WorkerBox();
        DeterministicScheduler s = Scheduler.deterministic();
        s.deploy(box);
        s.send(box.request, "bad");
        s.send(box.request, "good");
        s.runToCompletion();
        assertEquals(List.of("start bad", "start good", "done GOOD"), box.worker.log);
        ComponentFault f = box.collector.faults.get(0);
        assertEquals("workerBox.worker", f.componentPath());
        assertEquals("activity work", f.port());
        assertEquals("bad", f.message());
        assertEquals("cannot do bad", f.cause().getMessage());
    }

    static final class FaultExporter extends ComposedComponent {
        final InPort<Integer> in = inPort("in", Integer.class);
        final OutPort<ComponentFault> problems = outPort("problems", ComponentFault.class);
        final Mapper divider = subcomponent("divider", new Mapper(x -> 1 / x));

        FaultExporter() {
            connect(in, divider.in);
            connect(faults, problems);
        }
    }

    @Test
    void aComposedComponentCanExportItsFaultsOnAnOutPort() {
        FaultExporter e = new FaultExporter();
        List<ComponentFault> problems = new ArrayList<>();
        e.problems.observe(problems::add);
        DeterministicScheduler s = Scheduler.deterministic();
        s.deploy(e);
        s.send(e.in, 0);
        s.runUntilIdle();
        assertEquals(1, problems.size());
        assertEquals("faultExporter.divider", problems.get(0).componentPath());
        assertTrue(s.unhandledFaults().isEmpty());
    }

    @Test
    void aFaultOfAnActivityResultHandlerNamesTheActivityAndItsSubject() {
        WorkerBox box = new WorkerBox();
        DeterministicScheduler s = Scheduler.deterministic();
        box.done.observe(r -> {
            throw new IllegalStateException("display broken");
        });
        s.deploy(box);
        s.send(box.request, "fetch");
        s.runToCompletion();
        ComponentFault f = box.collector.faults.get(0);
        assertEquals("activity work", f.port());
        assertEquals("fetch", f.message());
        assertEquals("display broken", f.cause().getMessage());
    }
}
