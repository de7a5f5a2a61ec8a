package eu.brain.iot.eventing.integration.listing3;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/** The event of the paper's Listing 3: a robot is asked to resolve a collision. */
public class IresolveCollision extends BrainIoTEvent {
    public String robotId;
    public boolean resolved;

    public void resolveCollision() {
        resolved = true;
    }
}
