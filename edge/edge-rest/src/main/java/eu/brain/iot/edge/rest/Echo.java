package eu.brain.iot.edge.rest;

/**
 * What an error message may repeat of a request (a path, an id, a header): at most {@value #MAX_CHARS} characters,
 * then how long it was, so that a client cannot make the API send back kilobytes of its own input. Stateless.
 */
final class Echo {

    /** Longer than any path, provider or header value this API knows. */
    static final int MAX_CHARS = 120;

    private Echo() {
    }

    /** Longer than any message the device model writes about a request, which may quote its ids. */
    static final int MAX_MESSAGE_CHARS = 1_000;

    static String cut(String text) {
        return cut(text, MAX_CHARS);
    }

    static String cut(String text, int max) {
        if (text == null || text.length() <= max) {
            return text;
        }
        return text.substring(0, max) + "... (" + text.length() + " characters)";
    }
}
