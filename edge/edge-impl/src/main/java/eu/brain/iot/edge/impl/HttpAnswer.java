package eu.brain.iot.edge.impl;

/**
 * A device's HTTP answer.
 *
 * @param status    the HTTP status
 * @param body      the body's bytes
 * @param sentNanos {@link System#nanoTime()} when the request was written to the connection
 */
record HttpAnswer(int status, byte[] body, long sentNanos) {

    boolean ok() {
        return status >= 200 && status < 300;
    }
}
