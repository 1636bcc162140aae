package org.triad.runtime.component;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

/** MontiArc's time-synchronous semantics: one computation per slice, senders first, delayed ports one slice late, loops need a delay. */
class TimeSlicesTest {
    /** Adds one to each message; its out port is delayed when asked. */
    static final class Inc extends TimedComponent {
        final InPort<Integer> in = inPort("in", Integer.class);
        final OutPort<Integer> out;

        Inc(boolean delayed) {
            out = delayed ? delayedOutPort("out", Integer.class) : outPort("out", Integer.class);
        }

        @Override
        protected void compute() {
            Integer m = poll(in);
            emit(out, m == null ? null : m + 1);
        }
    }

    static final class Chain extends ComposedComponent {
        final InPort<Integer> in = inPort("in", Integer.class);
        final OutPort<Integer> out = outPort("out", Integer.class);
        final Inc second = subcomponent("second", new Inc(false));
        final Inc first;

        Chain(boolean delayedFirst) {
            first = subcomponent("first", new Inc(delayedFirst));
            connect(in, first.in);
            connect(first.out, second.in);
            connect(second.out, out);
        }
    }

    static final class Loop extends ComposedComponent {
        final Inc a = subcomponent("a", new Inc(false));
        final Inc b;

        Loop(boolean delayed) {
            b = subcomponent("b", new Inc(delayed));
            connect(a.out, b.in);
            connect(b.out, a.in);
        }
    }

    @Test
    void sendersComputeBeforeTheirReceiversWhateverTheModelOrder() {
        Chain chain = new Chain(false);
        List<Integer> seen = new ArrayList<>();
        chain.out.observe(seen::add);
        TimeSlices clock = TimeSlices.deploy(chain);
        assertEquals(List.of("chain.first", "chain.second"), clock.order());
        clock.send(chain.in, 1);
        clock.tick();
        assertEquals(List.of(3), seen, "both increments within the slice");
    }

    @Test
    void aDelayedPortDeliversInTheNextSlice() {
        Chain chain = new Chain(true);
        List<String> seen = new ArrayList<>();
        chain.out.observe(m -> seen.add(m.toString()));
        TimeSlices clock = TimeSlices.deploy(chain);
        clock.send(chain.in, 1);
        clock.tick();
        assertEquals(List.of(), seen);
        clock.tick();
        assertEquals(List.of("3"), seen);
        assertEquals(2, clock.slice());
    }

    @Test
    void aFeedbackLoopNeedsADelay() {
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> TimeSlices.deploy(new Loop(false)));
        assertTrue(e.getMessage().contains("feedback loop without a delayed port among [loop.a, loop.b]"), e.getMessage());
        TimeSlices clock = TimeSlices.deploy(new Loop(true));
        assertEquals(List.of("loop.a", "loop.b"), clock.order());
        clock.tick();
        assertEquals(List.of(), clock.scheduler().unhandledFaults());
    }
}
