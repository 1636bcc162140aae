package org.triad.vda5050.mqtt;

/** No MQTT broker answered at the address; the message names host and port. */
public final class BrokerUnreachableException extends RuntimeException {
    public BrokerUnreachableException(String message, Throwable cause) {
        super(message, cause);
    }
}
