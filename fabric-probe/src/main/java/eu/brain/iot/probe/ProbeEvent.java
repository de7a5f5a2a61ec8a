package eu.brain.iot.probe;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * A probe event: which run it belongs to, its number in that run (1, 2, ...), and the publisher's
 * {@code System.nanoTime()} just before it was handed to the bus (CLOCK_MONOTONIC on Linux: one clock for every
 * process and container of a machine, so a counter on another node of the same machine can subtract it).
 */
public class ProbeEvent extends BrainIoTEvent {
    public String run;
    public long seq;
    public long sentNanos;
}
