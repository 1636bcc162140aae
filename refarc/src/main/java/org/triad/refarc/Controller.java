package org.triad.refarc;

/**
 * The Controller: its behaviour is the automaton of {@code Controller.arc} (generated into
 * {@link ControllerTOP}). By hand only what the model leaves open: a message that no transition
 * takes (a reply to a request that is not outstanding, or one arriving in the wrong state) is a
 * fault with a message that says what was expected.
 */
public class Controller extends ControllerTOP {
    @Override
    protected void unhandled(String port, Object message) {
        long waitingFor = run.outstanding();
        throw new IllegalStateException("unexpected " + message + " while " + currentState().name().toLowerCase()
                + (waitingFor == 0 ? "" : " and waiting for request #" + waitingFor));
    }
}
