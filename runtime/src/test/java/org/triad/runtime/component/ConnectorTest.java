package org.triad.runtime.component;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.triad.runtime.component.TestComponents.Mapper;
import org.triad.runtime.component.TestComponents.Sink;

class ConnectorTest {

    /** A composition whose connections a test makes through {@link #link}. */
    static final class Box extends ComposedComponent {
        final InPort<Integer> in = inPort("in", Integer.class);
        final OutPort<Integer> out = outPort("out", Integer.class);
        final Mapper a = subcomponent("a", new Mapper(x -> x + 1));
        final Mapper b = subcomponent("b", new Mapper(x -> x * 10));
        final Sink<Integer> s1 = subcomponent("s1", new Sink<>(Integer.class));
        final Sink<Number> s2 = subcomponent("s2", new Sink<>(Number.class));
        final Sink<String> text = subcomponent("text", new Sink<>(String.class));

        void link(Port<?> from, Port<?>... to) {
            connect(from, to);
        }
    }

    @Test
    void fanOutDeliversToEveryReceiverInConnectionOrder() {
        Box box = new Box();
        box.link(box.in, box.a.in);
        box.link(box.a.out, box.s1.in, box.s2.in, box.out);
        DeterministicScheduler s = Scheduler.deterministic();
        List<Integer> outside = new java.util.ArrayList<>();
        box.out.observe(outside::add);
        s.deploy(box);
        s.send(box.in, 4);
        s.runUntilIdle();
        assertEquals(List.of(5), box.s1.received);
        assertEquals(List.<Number>of(5), box.s2.received);
        assertEquals(List.of(5), outside);
    }

    @Test
    void secondSenderToAnInPortFailsNamingBothSenders() {
        Box box = new Box();
        box.link(box.a.out, box.s1.in);
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> box.link(box.b.out, box.s1.in));
        assertTrue(e.getMessage().contains("box.s1.in"), e.getMessage());
        assertTrue(e.getMessage().contains("box.a.out"), e.getMessage());
        assertTrue(e.getMessage().contains("box.b.out"), e.getMessage());
    }

    @Test
    void aConnectorCannotNameATargetTwice() {
        Box box = new Box();
        assertThrows(IllegalArgumentException.class, () -> box.link(box.a.out, box.s1.in, box.s1.in));
        assertTrue(box.s1.in.source().isEmpty(), "a rejected connector leaves nothing behind");
    }

    @Test
    void typeIncompatibleConnectionFails() {
        Box box = new Box();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> box.link(box.a.out, box.text.in));
        assertTrue(e.getMessage().contains("type mismatch"), e.getMessage());
        // a subtype may flow into a supertype port, not the other way round
        box.link(box.a.out, box.s2.in);
    }

    @Test
    void connectorsMustFollowPortDirections() {
        Box box = new Box();
        assertThrows(IllegalArgumentException.class, () -> box.link(box.a.in, box.b.in));
        assertThrows(IllegalArgumentException.class, () -> box.link(box.a.out, box.b.out));
        assertThrows(IllegalArgumentException.class, () -> box.link(box.out, box.a.in));
        assertThrows(IllegalArgumentException.class, () -> box.link(box.in, box.in));
    }

    @Test
    void onlyDirectSubcomponentsCanBeConnected() {
        Box outer = new Box();
        Mapper stranger = new Mapper(x -> x);
        assertThrows(IllegalArgumentException.class, () -> outer.link(stranger.out, outer.s1.in));
    }

    @Test
    void runtimeFedFaultPortRejectsConnectorsAndEnvironment() {
        Box box = new Box();
        DeterministicScheduler s = Scheduler.deterministic();
        s.deploy(box);
        assertThrows(IllegalArgumentException.class, () -> s.send(box.faults, new ComponentFault("x", "y", null, new RuntimeException())));
    }

    @Test
    void structureIsFrozenAfterDeployment() {
        Box box = new Box();
        Scheduler.deterministic().deploy(box);
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> box.link(box.a.out, box.s1.in));
        assertTrue(e.getMessage().contains("deployed"), e.getMessage());
        assertThrows(IllegalStateException.class, () -> Scheduler.deterministic().deploy(box));
    }

    @Test
    void sendingBeforeDeploymentFailsClearly() {
        Mapper m = new Mapper(x -> x);
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> m.out.send(1));
        assertTrue(e.getMessage().contains("not deployed"), e.getMessage());
    }

    @Test
    void aMessageOfTheWrongTypeIsRejectedAtTheSender() {
        Mapper m = new Mapper(x -> x);
        Scheduler.deterministic().deploy(m);
        @SuppressWarnings({"unchecked", "rawtypes"})
        OutPort<Object> raw = (OutPort) m.out;
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> raw.send("text"));
        assertTrue(e.getMessage().contains("does not fit"), e.getMessage());
    }

    @Test
    void observingIsOnlyForRootPorts() {
        Box box = new Box();
        assertThrows(IllegalStateException.class, () -> box.a.out.observe(x -> { }));
    }
}
