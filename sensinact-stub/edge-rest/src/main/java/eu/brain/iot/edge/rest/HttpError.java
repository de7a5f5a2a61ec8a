package eu.brain.iot.edge.rest;

/**
 * A request that cannot be served, with the status to answer and a message for the caller that says what was
 * wrong and what exists instead. Thrown by the request handlers, turned into a JSON error by {@link Replies}.
 */
final class HttpError extends RuntimeException {
    private static final long serialVersionUID = 1L;

    final int status;
    /** For 405: the methods the resource accepts (the {@code Allow} header), else {@code null}. */
    final String allow;

    HttpError(int status, String message) {
        this(status, message, null);
    }

    private HttpError(int status, String message, String allow) {
        super(message, null, false, false); // no stack trace: it is an answer, not a bug
        this.status = status;
        this.allow = allow;
    }

    static HttpError notFound(String message) {
        return new HttpError(404, message);
    }

    static HttpError badRequest(String message) {
        return new HttpError(400, message);
    }

    static HttpError methodNotAllowed(String method, String path, String allow, String hint) {
        return new HttpError(405, method + " is not allowed on " + path + "; use " + allow
                + (hint == null ? "" : " (" + hint + ")"), allow);
    }
}
