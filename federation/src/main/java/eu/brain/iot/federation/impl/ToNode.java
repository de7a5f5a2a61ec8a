package eu.brain.iot.federation.impl;

import java.util.List;
import java.util.Map;
import java.util.function.Function;

import eu.brain.iot.eventing.spi.EventForwarder;

/**
 * The forwarders to one node: each event kept in the node's {@link Outbox} and sent by the {@link Sender}. On the
 * publisher's thread when the outbox has room (and exists: opening its journal is for a delivery worker), else on a
 * delivery worker of the bus, waiting for room.
 * <p>
 * Threads: publishers and the bus's delivery workers; it keeps no state of its own (the outbox synchronises itself).
 */
final class ToNode implements EventForwarder {

    private final String destination;
    /** The destination's outbox, opened when missing. */
    private final Function<String, Outbox> outbox;
    /** The destination's outbox if it is open, else {@code null}. */
    private final Function<String, Outbox> open;
    private final Wire wire;
    /** Wakes the sender. */
    private final Runnable wake;

    ToNode(String destination, Function<String, Outbox> outbox, Function<String, Outbox> open, Wire wire,
            Runnable wake) {
        this.destination = destination;
        this.outbox = outbox;
        this.open = open;
        this.wire = wire;
        this.wake = wake;
    }

    @Override
    public void forward(String type, List<String> names, Map<String, Object> data) {
        try {
            outbox.apply(destination).append(seq -> wire.event(seq, type, names, data));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("the forwarder to " + destination + " was stopped while it waited "
                    + "for room", e);
        }
        wake.run();
    }

    @Override
    public boolean forwardNow(String type, List<String> names, Map<String, Object> data) {
        Outbox o = open.apply(destination);
        if (o == null || !o.tryAppend(seq -> wire.event(seq, type, names, data))) {
            return false;
        }
        wake.run();
        return true;
    }
}
