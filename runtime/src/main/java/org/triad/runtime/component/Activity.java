package org.triad.runtime.component;

import java.util.concurrent.Callable;

/** Long-running work of a component whose result comes back to it as a message. */
final class Activity<R> {
    final AtomicComponent owner;
    final String name;
    final Object subject;
    private final Callable<? extends R> work;
    private final MessageHandler<? super R> onResult;

    Activity(AtomicComponent owner, String name, Object subject, Callable<? extends R> work, MessageHandler<? super R> onResult) {
        Component.requireIdentifier(name, "activity");
        this.owner = owner;
        this.name = name;
        this.subject = subject;
        this.work = work;
        this.onResult = onResult;
    }

    String label() {
        return "activity " + name;
    }

    /**
     * Runs the work on the calling thread, then hands its result to the scheduler as a message for
     * the owner; a throwing work becomes a fault.
     */
    void runOn(Scheduler scheduler) {
        R result;
        try {
            result = work.call();
        } catch (Throwable t) {
            scheduler.fault(owner, label(), subject, t);
            return;
        }
        scheduler.enqueue(new Envelope(owner) {
            @Override
            String label() {
                return Activity.this.label();
            }

            @Override
            Object message() {
                // the subject, not the result: it tells whoever receives the fault which request failed
                return subject;
            }

            @Override
            void run() throws Exception {
                onResult.handle(result);
            }
        });
    }

    @Override
    public String toString() {
        return owner.path() + " " + label() + " on " + subject;
    }
}
