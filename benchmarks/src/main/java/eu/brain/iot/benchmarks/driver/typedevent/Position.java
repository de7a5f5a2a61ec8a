package eu.brain.iot.benchmarks.driver.typedevent;

/** The benchmark event on the typed event bus: a DTO with four small fields. */
public class Position {
    public String robotId;
    public int x;
    public int y;
    /** {@link System#nanoTime()} just before {@code deliver}, for latency. */
    public long sentNanos;
}
