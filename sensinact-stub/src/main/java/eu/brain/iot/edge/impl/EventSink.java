package eu.brain.iot.edge.impl;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/** Where the edge's events go: the event bus in a framework, a list in a test. */
@FunctionalInterface
interface EventSink {
    void publish(BrainIoTEvent event);
}
