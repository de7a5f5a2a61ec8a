package eu.brain.iot.eventing.integration.tb;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * An event class of which each test bundle built by {@code TestBundles} carries its own copy, as two
 * independently built behaviours would.
 */
public class CopyEvent extends BrainIoTEvent {
    public String robotId;
    public Position at;
}
