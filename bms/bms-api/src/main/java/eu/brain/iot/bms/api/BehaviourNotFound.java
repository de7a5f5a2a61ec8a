package eu.brain.iot.bms.api;

import java.util.List;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * No repository offers a behaviour that consumes an event type (nor its supertypes and interfaces). Published once
 * per search; the type's events are then counted as unhandled, without searching again, until
 * {@link #retryAfter}.
 */
public class BehaviourNotFound extends BrainIoTEvent {
    /** The event type that had no consumer. */
    public String eventType;
    /** The types searched for: the event's type, then its supertypes and interfaces. */
    public List<String> searched;
    /** How many events of the type were held while the repositories were searched (given up on now). */
    public int heldEvents;
    /** Until when (milliseconds since the epoch) the repositories are not searched again for this type. */
    public long retryAfter;
}
