package eu.brain.iot.federation.impl;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.function.Function;

import eu.brain.iot.federation.impl.Journal.Pending;
import eu.brain.iot.federation.impl.RemoteNode.Presence;

/**
 * Writes the {@link Outbox}es' journals, takes batches of events from them and publishes them, signed, to the nodes
 * they are for; sends again what was not acknowledged in time. Between its rounds (at least once a second) it tells
 * {@link LastConnected} that this node is connected, if it is: a late time only makes a clean start likelier. An
 * outbox of a node that is not online keeps its events until the node is back (its acknowledgement could not come).
 * <p>
 * Threads: its own thread ({@code brain-iot-fabric-out}) sends; anyone may {@link #wake} it; the resend check runs
 * on the fabric's inbound thread. The outboxes synchronise themselves.
 */
final class Sender {

    private final Settings settings;
    private final Wire wire;
    private final Topics topics;
    private final MqttLink link;
    private final Collection<Outbox> outboxes;
    private final Function<String, RemoteNode> nodes;
    private final Host host;
    private final LastConnected lastConnected;
    private final Thread thread;
    private final Object signal = new Object();
    private boolean wanted;
    private volatile boolean closed;

    Sender(Settings settings, Wire wire, Topics topics, MqttLink link, Collection<Outbox> outboxes,
            Function<String, RemoteNode> nodes, Host host, LastConnected lastConnected) {
        this.settings = settings;
        this.wire = wire;
        this.topics = topics;
        this.link = link;
        this.outboxes = outboxes;
        this.nodes = nodes;
        this.host = host;
        this.lastConnected = lastConnected;
        this.thread = new Thread(this::loop, "brain-iot-fabric-out");
        thread.setDaemon(true);
    }

    void start() {
        thread.start();
    }

    void wake() {
        synchronized (signal) {
            wanted = true;
            signal.notifyAll();
        }
    }

    private void loop() {
        while (!closed) {
            try {
                synchronized (signal) {
                    while (!wanted && !closed) {
                        signal.wait(1000);
                    }
                    wanted = false;
                }
                if (link.isConnected()) {
                    lastConnected.connected(System.currentTimeMillis(), host, settings.fabric());
                }
                for (Outbox outbox : outboxes) {
                    outbox.writeJournal(); // connected or not: what was accepted is kept if this node is killed
                }
                boolean more = true;
                while (more && !closed && link.isConnected()) {
                    more = false;
                    for (Outbox outbox : outboxes) {
                        more |= sendSome(outbox);
                    }
                }
            } catch (InterruptedException e) {
                return;
            } catch (IOException | RuntimeException e) {
                if (!closed) {
                    host.warn("Fabric {}: sending failed ({}); unacknowledged events are sent again",
                            settings.fabric(), e.getMessage());
                }
            }
        }
    }

    /** @return whether the outbox has more to send */
    private boolean sendSome(Outbox outbox) throws IOException, InterruptedException {
        outbox.writeJournal(); // what was appended since the loop's first write
        if (!outbox.hasUnsent()) {
            return false;
        }
        RemoteNode node = nodes.apply(outbox.destination());
        if (node.status != Presence.ONLINE) {
            return false;
        }
        Outbox.Taken taken = outbox.takeBatch(settings.batchMaxEvents());
        List<Pending> batch = taken.events();
        if (batch.isEmpty()) {
            return false;
        }
        List<byte[]> events = new ArrayList<>(batch.size());
        batch.forEach(p -> events.add(p.json()));
        byte[] payload = wire.batch(settings.node(), outbox.destination(), taken.epoch(),
                System.currentTimeMillis(), events);
        link.publish(topics.events(outbox.destination(), settings.node()), payload, false);
        outbox.sent(taken); // not when the publication fails: its events go after the reconnection
        return outbox.hasUnsent();
    }

    /** Send again what an online node did not acknowledge within the resend timeout (or at once if forced). */
    void resendCheck(boolean force) {
        boolean any = false;
        for (Outbox outbox : outboxes) {
            if (nodes.apply(outbox.destination()).status == Presence.ONLINE) {
                any |= outbox.rewind(force, settings.resendTimeoutMillis()) > 0;
            }
        }
        if (any || force || outboxes.stream().anyMatch(Outbox::hasUnsent)) {
            wake(); // also a safety net: nothing kept waits longer than one check for the sender
        }
    }

    void close() {
        closed = true;
        wake();
        thread.interrupt();
        try {
            thread.join(5000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
