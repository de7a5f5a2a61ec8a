package eu.brain.iot.bms.integration.tb;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/** A second event type consumed by the same behaviour bundle as {@link Order}. */
public class Refill extends BrainIoTEvent {
    public String publisher;
    public int seq;
}
