package eu.brain.iot.benchmarks.behaviour.event;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/** The event that brings the probe behaviour: each of its bundles (driver, probe) has its own copy of the class. */
public class InstallBenchEvent extends BrainIoTEvent {
    public String publisher;
    public int seq;
    public long sentNanos;
}
