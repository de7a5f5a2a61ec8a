package eu.brain.iot.federation.impl;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.function.Consumer;
import java.util.function.Function;

import eu.brain.iot.federation.impl.Wire.MalformedException;

/**
 * Batches of events for this node's behaviours, taken on Paho's callback thread: one thread hand-off less between the
 * broker and a behaviour than through the fabric's inbound thread. Only a batch that passes every check (names,
 * signature, sender and receiver, age) is taken here; anything else goes to the inbound thread, which checks it again
 * with the same arrival time and refuses it with its reason, so a batch that passes is never queued behind the ones
 * taken here (the publisher's order holds).
 * <p>
 * Threads: Paho's callback thread; what it changes ({@link Inboxes}, {@link Refusals#verified}, the node table and
 * its counters) is safe to share with the inbound thread.
 */
final class DirectBatches {

    private final Settings settings;
    private final FabricKey key;
    private final Topics topics;
    private final Wire wire;
    private final Refusals refusals;
    private final Inboxes inboxes;
    private final Function<String, RemoteNode> nodes;
    private final Consumer<Exception> stateNotWritten;

    DirectBatches(Settings settings, FabricKey key, Topics topics, Wire wire, Refusals refusals, Inboxes inboxes,
            Function<String, RemoteNode> nodes, Consumer<Exception> stateNotWritten) {
        this.settings = settings;
        this.key = key;
        this.topics = topics;
        this.wire = wire;
        this.refusals = refusals;
        this.inboxes = inboxes;
        this.nodes = nodes;
        this.stateNotWritten = stateNotWritten;
    }

    /**
     * @param at when the message arrived (epoch milliseconds)
     * @return whether the message was a batch of events for this node that passed every check, taken
     */
    boolean took(String topic, byte[] payload, String signature, long at) {
        Topics.Parsed t = topics.parse(topic);
        if (t == null || !Topics.EVENTS.equals(t.kind()) || !t.node().equals(settings.node())) {
            return false;
        }
        String from = t.other();
        if (from == null || !Settings.NAME.matcher(from).matches()
                || Refusals.check(key, topic, payload, signature) != null) {
            return false;
        }
        Wire.Batch batch;
        try {
            batch = wire.readBatch(payload);
        } catch (MalformedException e) {
            return false;
        }
        if (!batch.from().equals(from) || !batch.to().equals(settings.node()) || !settings.inTime(batch.sent(), at)) {
            return false;
        }
        refusals.verified();
        try {
            inboxes.accept(from, batch, nodes.apply(from).stats);
        } catch (IOException | UncheckedIOException e) {
            stateNotWritten.accept(e); // thrown on Paho's thread, it would end the connection; the batch comes again
        }
        return true;
    }
}
