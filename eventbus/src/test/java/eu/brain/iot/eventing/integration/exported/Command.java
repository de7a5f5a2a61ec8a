package eu.brain.iot.eventing.integration.exported;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/** A supertype of events, in a package the test bundle exports, as an API bundle exports its events. */
public class Command extends BrainIoTEvent {
    public String deviceId;
}
