package org.triad.vda5050.protocol;

/** A message that is not JSON, violates its schema, or speaks another major version; the message is one line. */
public final class VdaMessageException extends RuntimeException {
    public VdaMessageException(String message) {
        super(message);
    }
}
