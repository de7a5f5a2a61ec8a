package eu.brain.iot.containers.probe;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/** A probe event: which run it belongs to and its number in that run (1, 2, ...). */
public class ProbeEvent extends BrainIoTEvent {
    public String run;
    public long seq;
}
