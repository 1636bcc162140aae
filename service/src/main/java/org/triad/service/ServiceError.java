package org.triad.service;

/**
 * A problem the service reports instead of a stack trace: at start-up one line on stderr and exit
 * code 2, in a request an HTTP status with a JSON body {@code {"error": ..., "message": ...}}.
 */
public class ServiceError extends RuntimeException {
    private static final long serialVersionUID = 1L;

    private final int httpStatus;
    private final String code;

    public ServiceError(int httpStatus, String code, String message) {
        super(message);
        this.httpStatus = httpStatus;
        this.code = code;
    }

    /** A start-up error (bad arguments, models, database): one line, exit code 2. */
    public static ServiceError startup(String message) {
        return new ServiceError(0, "startup", message);
    }

    public int httpStatus() {
        return httpStatus;
    }

    /** A stable machine-readable code, e.g. {@code unknown-task}, {@code not-found}. */
    public String code() {
        return code;
    }
}
