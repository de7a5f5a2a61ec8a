package eu.brain.iot.eventing.integration;

/** An interface an event type may implement; consumers may name it. */
public interface Robotic {
}
