package eu.brain.iot.eventing.integration.tb;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/** An event no behaviour consumes until the bundle of {@link HoldConsumerActivator} is installed. */
public class HoldEvent extends BrainIoTEvent {
    public String publisher;
    public int seq;
}
