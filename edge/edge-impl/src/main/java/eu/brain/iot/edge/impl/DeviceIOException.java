package eu.brain.iot.edge.impl;

import java.io.IOException;

/** A request to a device that got no usable answer; the message says what happened, for a person to read. */
final class DeviceIOException extends IOException {
    private static final long serialVersionUID = 1L;

    /**
     * True when the request never left the edge because every connection to the host stayed busy: the edge's own
     * congestion, not a sign that the device fails.
     */
    final boolean notSent;

    DeviceIOException(String message) {
        this(message, false);
    }

    DeviceIOException(String message, boolean notSent) {
        super(message);
        this.notSent = notSent;
    }
}
