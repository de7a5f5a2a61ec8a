package eu.brain.iot.bms.integration.tb;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/** An event that no behaviour of the framework consumes: only the behaviour in the test repository does. */
public class Order extends BrainIoTEvent {
    public String publisher;
    public int seq;
}
