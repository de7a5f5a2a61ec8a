package eu.brain.iot.edge.api;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * An order for one robot or door, consumed by the edge, which performs it over the device's REST API and then
 * publishes a {@link CommandOutcome} with the same {@link #commandId}. Commands are never retried by the edge
 * (an order is not idempotent): a rejected command is for the sender to decide about.
 */
public abstract class EdgeCommand extends BrainIoTEvent {

    /** Chosen by the sender to match the outcome; the edge makes one up when it is {@code null}. */
    public String commandId;
    /** The robot or door id, for example {@code robot1} or {@code door1}. */
    public String deviceId;
}
