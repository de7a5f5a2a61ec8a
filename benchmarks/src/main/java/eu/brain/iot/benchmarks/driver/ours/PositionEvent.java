package eu.brain.iot.benchmarks.driver.ours;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/** The benchmark event on our bus: four small fields on top of the {@link BrainIoTEvent} header. */
public class PositionEvent extends BrainIoTEvent {
    public String robotId;
    public int x;
    public int y;
    /** {@link System#nanoTime()} just before {@code deliver}, for latency. */
    public long sentNanos;
}
