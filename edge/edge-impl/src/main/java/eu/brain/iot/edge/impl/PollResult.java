package eu.brain.iot.edge.impl;

/**
 * What became of one poll: made on an HTTP thread by {@link FleetApi#poll}, handed to the fleet thread, which
 * handles it with a {@link Handler}. Immutable.
 */
sealed interface PollResult {

    /** Calls the handler's method for this kind of result, for the poll of {@code device}. */
    <D> void handle(D device, Handler<D> handler);

    /** The fleet thread's treatment of each kind of result; {@code D} is what the poll was of. */
    interface Handler<D> {
        void answered(D device, Answered answer);

        void unchanged(D device, Unchanged unchanged);

        void failed(D device, Failed failure);

        void notSent(D device, NotSent notSent);
    }

    /**
     * A new answer, parsed.
     *
     * @param body      its bytes: an answer with the same bytes next time is {@link Unchanged}
     * @param sentNanos when the request was written ({@link System#nanoTime()})
     */
    record Answered(DeviceAnswer answer, byte[] body, long sentNanos) implements PollResult {
        @Override
        public <D> void handle(D device, Handler<D> handler) {
            handler.answered(device, this);
        }
    }

    /** An answer byte for byte equal to the one the device's values came from: nothing to parse or set. */
    record Unchanged(long sentNanos) implements PollResult {
        @Override
        public <D> void handle(D device, Handler<D> handler) {
            handler.unchanged(device, this);
        }
    }

    /** No usable answer: the device failed (timeout, error status, bad JSON, connection lost). */
    record Failed(String reason) implements PollResult {
        @Override
        public <D> void handle(D device, Handler<D> handler) {
            handler.failed(device, this);
        }
    }

    /** The request never left the edge: every connection stayed busy (the edge's congestion, not the device's). */
    record NotSent(String reason) implements PollResult {
        @Override
        public <D> void handle(D device, Handler<D> handler) {
            handler.notSent(device, this);
        }
    }
}
