package eu.brain.iot.eventing.integration;

/** A subtype, to check that consumers of the supertype receive it. */
public class MovedEvent extends PositionEvent implements Robotic {
    public String from;
}
