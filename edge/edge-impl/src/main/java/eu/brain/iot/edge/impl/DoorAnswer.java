package eu.brain.iot.edge.impl;

import java.util.List;

/** A door's answer to {@code GET /{door}/door_controller/state}, checked by {@link AnswerParser}. */
record DoorAnswer(String id, int x, int y, String state, double data, int stepsLeft) implements DeviceAnswer {

    @Override
    public List<Resource> resources() {
        return List.of(new Resource("position", "x", x), new Resource("position", "y", y),
                new Resource("door", "state", state), new Resource("door", "open", data == 1.0),
                new Resource("door", "stepsLeft", stepsLeft));
    }

    @Override
    public void announce(EdgeEvents events, DeviceAnswer before, java.time.Instant at) {
        events.door((DoorAnswer) before, this, at); // a provider's answers are all of its kind
    }
}
