package eu.brain.iot.behaviours.door.impl;

import eu.brain.iot.edge.api.CommandOutcome;

/**
 * What {@link DoorBinding} hands from the bus to its own thread: one kind per edge event it consumes, carrying just
 * what the binding thread needs. Threads: made on the bus's delivery thread by {@link DoorBinding#notify} (from the
 * event, by the table {@code DoorBinding.INPUTS}), immutable, handled on the binding thread with a {@link Handler}.
 */
sealed interface DoorInput {

    /** Calls the handler's method for this kind of input. */
    void handle(Handler handler);

    /** The binding thread's treatment of each kind of input. */
    interface Handler {
        void outcome(Outcome outcome);

        void stateChanged(StateChanged changed);
    }

    /**
     * The edge's answer to a command ({@code CommandOutcome}), for {@link DoorControl#outcome}, which takes the event
     * itself: an event is not changed once published.
     */
    record Outcome(CommandOutcome outcome) implements DoorInput {
        @Override
        public void handle(Handler handler) {
            handler.outcome(this);
        }
    }

    /** A door's state changed ({@code DoorStateChanged}): {@code state} is the new one ({@code "closed"}, ...). */
    record StateChanged(String door, String state) implements DoorInput {
        @Override
        public void handle(Handler handler) {
            handler.stateChanged(this);
        }
    }
}
