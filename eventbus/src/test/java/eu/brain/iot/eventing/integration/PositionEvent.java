package eu.brain.iot.eventing.integration;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/** A robot position: the shape of the events the edge publishes. */
public class PositionEvent extends BrainIoTEvent {
    public String robotId;
    public int x;
    public int y;
    public long seq;
    public int[] path;

    public PositionEvent() {
    }

    public PositionEvent(String robotId, int x, int y, long seq) {
        this.robotId = robotId;
        this.x = x;
        this.y = y;
        this.seq = seq;
    }
}
