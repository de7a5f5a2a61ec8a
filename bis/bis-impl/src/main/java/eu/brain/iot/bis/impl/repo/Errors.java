package eu.brain.iot.bis.impl.repo;

/** Turns an exception into words for people: its message, or its kind and its cause's message when it has none. */
public final class Errors {

    private Errors() {
    }

    /** @return e.g. {@code connection refused (ConnectException)}, never {@code null} */
    public static String describe(Throwable e) {
        for (Throwable t = e; t != null; t = t.getCause()) {
            String message = t.getMessage();
            if (message != null && !message.isBlank()) {
                return t == e ? message : message + " (" + e.getClass().getSimpleName() + ")";
            }
            if (t.getCause() == null || t.getCause() == t) {
                break;
            }
        }
        return kind(e);
    }

    private static String kind(Throwable e) {
        String name = e.getClass().getSimpleName();
        return switch (name) {
        case "ConnectException" -> "connection refused or unreachable (ConnectException)";
        case "HttpConnectTimeoutException" -> "no connection within the timeout (HttpConnectTimeoutException)";
        case "HttpTimeoutException" -> "no answer within the timeout (HttpTimeoutException)";
        case "ClosedChannelException" -> "the connection was closed (ClosedChannelException)";
        case "EOFException" -> "the connection ended early (EOFException)";
        default -> name;
        };
    }
}
