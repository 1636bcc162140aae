package org.triad.refarc;

/**
 * A message that belongs to one request of the Controller. The id lets the Controller tell whether
 * a fault or a reply concerns the step it is waiting for.
 */
public interface Correlated {
    long requestId();
}
