package org.triad.runtime.component;

/** One unit of work for an atomic component: a message at an in port, or an activity's result. */
abstract class Envelope {
    final AtomicComponent target;

    Envelope(AtomicComponent target) {
        this.target = target;
    }

    /** The port name or {@code activity NAME}, for faults. */
    abstract String label();

    abstract Object message();

    abstract void run() throws Exception;

    static Envelope message(AtomicComponent target, InPort<?> port, Object message) {
        return new Envelope(target) {
            @Override
            String label() {
                return port.name();
            }

            @Override
            Object message() {
                return message;
            }

            @Override
            void run() throws Exception {
                target.handle(port, message);
            }
        };
    }
}
