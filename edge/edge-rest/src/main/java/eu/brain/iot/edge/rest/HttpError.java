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
    /** The header, query parameter or body part at fault ({@code "Host"}, {@code "body"}), or {@code null}. */
    final String field;
    /** Whether the connection must close after the answer (a body left unread, a client too slow). */
    final boolean close;

    HttpError(int status, String message) {
        this(status, message, null, null, false);
    }

    private HttpError(int status, String message, String allow, String field, boolean close) {
        super(message, null, false, false); // no stack trace: it is an answer, not a bug
        this.status = status;
        this.allow = allow;
        this.field = field;
        this.close = close;
    }

    /** An error about one field of the request: a header, a query parameter, the body. */
    static HttpError about(int status, String field, String message) {
        return new HttpError(status, message, null, field, false);
    }

    /** Like {@link #about}, and the connection closes after the answer (what is left of the request is not read). */
    static HttpError closing(int status, String field, String message) {
        return new HttpError(status, message, null, field, true);
    }

    static HttpError notFound(String message) {
        return new HttpError(404, message);
    }

    static HttpError badRequest(String message) {
        return new HttpError(400, message);
    }

    static HttpError methodNotAllowed(String method, String path, String allow, String hint) {
        return new HttpError(405, method + " is not allowed on " + path + "; use " + allow
                + (hint == null ? "" : " (" + hint + ")"), allow, null, false);
    }
}
