package org.triad.runtime.component;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.IntStream;
import org.junit.jupiter.api.Test;
import org.triad.runtime.component.TestComponents.Mapper;
import org.triad.runtime.component.TestComponents.Sink;

class ThreadedSchedulerTest {
    private static final Duration PATIENCE = Duration.ofSeconds(30);

    static final class Pipeline extends ComposedComponent {
        final InPort<Integer> in = inPort("in", Integer.class);
        final Mapper inc = subcomponent("inc", new Mapper(x -> x + 1));
        final Mapper dbl = subcomponent("dbl", new Mapper(x -> x * 2));
        final Sink<Integer> sink = subcomponent("sink", new Sink<>(Integer.class, -2));

        Pipeline() {
            connect(in, inc.in);
            connect(inc.out, dbl.in);
            connect(dbl.out, sink.in);
        }
    }

    @Test
    void messagesKeepTheirOrderAlongAPipeline() throws Exception {
        try (ThreadedScheduler s = Scheduler.threaded(2)) {
            Pipeline p = new Pipeline();
            s.deploy(p);
            IntStream.range(0, 2000).forEach(i -> s.send(p.in, i));
            assertTrue(s.awaitIdle(PATIENCE));
            List<Integer> expected = IntStream.range(0, 2000).map(i -> (i + 1) * 2).boxed().toList();
            assertEquals(expected, p.sink.received);
        }
    }

    @Test
    void aThrowingHandlerDoesNotStopProcessing() throws Exception {
        try (ThreadedScheduler s = Scheduler.threaded(1)) {
            Pipeline p = new Pipeline();
            List<ComponentFault> faults = java.util.Collections.synchronizedList(new ArrayList<>());
            s.onUnhandledFault(faults::add);
            s.deploy(p);
            s.send(p.in, -2); // (−2+1)*2 = −2 poisons the sink
            IntStream.range(0, 100).forEach(i -> s.send(p.in, i));
            assertTrue(s.awaitIdle(PATIENCE));
            assertEquals(100, p.sink.received.size());
            assertEquals(1, faults.size());
            assertEquals("pipeline.sink", faults.get(0).componentPath());
        }
    }

    /** Two upstream components feed one component through two ports; it must never run two handlers at once. */
    static final class FanIn extends ComposedComponent {
        final InPort<Integer> left = inPort("left", Integer.class);
        final InPort<Integer> right = inPort("right", Integer.class);
        final Mapper l = subcomponent("l", new Mapper(x -> x));
        final Mapper r = subcomponent("r", new Mapper(x -> x));
        final Joiner joiner = subcomponent("joiner", new Joiner());

        FanIn() {
            connect(left, l.in);
            connect(right, r.in);
            connect(l.out, joiner.a);
            connect(r.out, joiner.b);
        }
    }

    static final class Joiner extends AtomicComponent {
        final InPort<Integer> a = inPort("a", Integer.class);
        final InPort<Integer> b = inPort("b", Integer.class);
        final AtomicBoolean busy = new AtomicBoolean();
        final AtomicInteger overlaps = new AtomicInteger();
        int count; // deliberately unsynchronised: serial handling makes it safe

        Joiner() {
            on(a, this::count);
            on(b, this::count);
        }

        private void count(Integer x) {
            if (!busy.compareAndSet(false, true)) {
                overlaps.incrementAndGet();
            }
            count++;
            busy.set(false);
        }
    }

    @Test
    void eachComponentHandlesOneMessageAtATime() throws Exception {
        try (ThreadedScheduler s = Scheduler.threaded(3)) {
            FanIn f = new FanIn();
            s.deploy(f);
            Thread other = new Thread(() -> IntStream.range(0, 5000).forEach(i -> s.send(f.right, i)));
            other.start();
            IntStream.range(0, 5000).forEach(i -> s.send(f.left, i));
            other.join();
            assertTrue(s.awaitIdle(PATIENCE));
            assertEquals(0, f.joiner.overlaps.get());
            assertEquals(10000, f.joiner.count);
        }
    }

    static final class Busy extends AtomicComponent {
        final InPort<String> start = inPort("start", String.class);
        final InPort<String> ping = inPort("ping", String.class);
        final OutPort<String> finished = outPort("finished", String.class);

        Busy(CountDownLatch release, CountDownLatch pinged) {
            on(start, s -> startActivity("longAction", s, () -> {
                if (!release.await(30, TimeUnit.SECONDS)) {
                    throw new IllegalStateException("never released");
                }
                return s + " finished";
            }, finished::send));
            on(ping, p -> pinged.countDown());
        }
    }

    @Test
    void aLongActivityDoesNotBlockItsComponent() throws Exception {
        CountDownLatch release = new CountDownLatch(1);
        CountDownLatch pinged = new CountDownLatch(1);
        try (ThreadedScheduler s = Scheduler.threaded(1)) {
            Busy b = new Busy(release, pinged);
            List<String> out = java.util.Collections.synchronizedList(new ArrayList<>());
            b.finished.observe(out::add);
            s.deploy(b);
            s.send(b.start, "move");
            s.send(b.ping, "are you there?");
            assertTrue(pinged.await(30, TimeUnit.SECONDS), "the ping was handled while the activity still ran");
            assertTrue(out.isEmpty());
            release.countDown();
            assertTrue(s.awaitIdle(PATIENCE));
            assertEquals(List.of("move finished"), out);
        }
    }
}
