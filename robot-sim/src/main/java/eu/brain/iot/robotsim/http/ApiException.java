package eu.brain.iot.robotsim.http;

/** A request that gets an error answer {@code {"error": message, "field": field}}; nothing was changed. */
final class ApiException extends Exception {
    private static final long serialVersionUID = 1L;
    private final int status;
    private final String field;

    ApiException(int status, String field, String message) {
        super(message);
        this.status = status;
        this.field = field;
    }

    int status() {
        return status;
    }

    String field() {
        return field;
    }
}
