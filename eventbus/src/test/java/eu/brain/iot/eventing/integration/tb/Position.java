package eu.brain.iot.eventing.integration.tb;

/** A nested data object inside {@link CopyEvent}. */
public class Position {
    public int x;
    public int y;
}
