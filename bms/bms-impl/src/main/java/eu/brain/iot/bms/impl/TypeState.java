package eu.brain.iot.bms.impl;

import java.util.List;
import java.util.concurrent.atomic.LongAdder;

import eu.brain.iot.eventing.spi.UnhandledEventPolicy.Disposition;

/**
 * Where the BMS stands with one event type that no behaviour consumes. Immutable (but for a counter): a state is
 * replaced as a whole with {@code ConcurrentMap.replace(type, old, new)}, so that the publishers' threads, which
 * only ever start a new episode (no state, or an expired one), and the BMS's thread, which moves an episode on,
 * never overwrite each other's step.
 * <p>
 * {@code since} is when the episode's first event came: durations and the install deadline count from it.
 */
sealed interface TypeState {

    /** The event's type, then its supertypes and interfaces: what the repositories are searched for. */
    List<String> searched();

    long since();

    /** Which install attempt the episode is at, from 1; 0 in a rest. */
    default int attempt() {
        return 0;
    }

    /** What the bus does with an event of the type in this state, at {@code now}; {@code null}: a new episode. */
    Disposition disposition(long now);

    /** The repositories are being searched (a remote installer answers later); events are held. */
    record Searching(List<String> searched, long since, int attempt) implements TypeState {
        @Override
        public Disposition disposition(long now) {
            return Disposition.HOLD;
        }
    }

    /** An install was asked for; events are held. {@code job} identifies the request (several types may share it). */
    record Installing(List<String> searched, long since, String behaviour, int attempt, long job)
            implements TypeState {
        @Override
        public Disposition disposition(long now) {
            return Disposition.HOLD;
        }
    }

    /** The last attempt failed; the next one is at {@code nextRetry}. Events are held. */
    record RetryWait(List<String> searched, long since, String behaviour, int attempt, long nextRetry,
            String lastReason) implements TypeState {
        @Override
        public Disposition disposition(long now) {
            return Disposition.HOLD;
        }
    }

    /**
     * Installed: the installer said its behaviours are registered with the bus. Until {@code graceUntil} events
     * are still held (the bus may not have seen the registration yet); after that an unhandled event means the
     * behaviour went away (or does not take the event), and a new episode starts.
     */
    record Installed(List<String> searched, long since, String behaviour, long graceUntil) implements TypeState {
        @Override
        public Disposition disposition(long now) {
            return now < graceUntil ? Disposition.HOLD : null;
        }

        @Override
        public int attempt() {
            return 1;
        }
    }

    /**
     * Events are not held and no search is made until {@code until}; then a new episode starts. They go to the
     * consumers of last resort if there are any (a dashboard, a logger), else the bus counts them as unhandled:
     * either way the publisher never waits for an install.
     */
    record Resting(List<String> searched, long since, Rest kind, String behaviour, long until, String reason,
            LongAdder unhandled) implements TypeState {
        @Override
        public Disposition disposition(long now) {
            if (now >= until) {
                return null;
            }
            unhandled.increment();
            return Disposition.LAST_RESORT;
        }
    }

    /** Why a type rests. */
    enum Rest {
        /** No repository offers a behaviour for it. */
        NOT_FOUND,
        /** An operator removed its behaviour ({@code bis:uninstall}): not installed again automatically. */
        REMOVED_BY_OPERATOR,
        /** Installing its behaviour kept failing until the deadline. */
        GAVE_UP,
        /** Its behaviour is installed and active but does not take these events (its filter). */
        NOT_TAKEN
    }
}
