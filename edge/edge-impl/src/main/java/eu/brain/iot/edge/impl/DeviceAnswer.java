package eu.brain.iot.edge.impl;

import java.util.List;

/**
 * A device's answer to a poll, checked by {@link AnswerParser}: a robot's or a door's; or a cart or the map read from
 * the fleet's world ({@link WorldAnswer}). Each kind says which
 * resources of the device model it sets, so the {@link DeviceStore} needs to know no kind of device.
 */
sealed interface DeviceAnswer permits RobotAnswer, DoorAnswer, WorldAnswer.Cart, WorldAnswer.Map {

    /** The device's id. */
    String id();

    /** The resource values this answer gives its provider. */
    List<Resource> resources();

    /**
     * Tell the events of what changed since {@code before} (an answer of the same device, {@code null} the first
     * time) to the event side.
     */
    void announce(EdgeEvents events, DeviceAnswer before, java.time.Instant at);

    /** One resource's value: {@code service}, {@code resource}, a String, Number or Boolean, or {@code null}. */
    record Resource(String service, String resource, Object value) {
    }
}
