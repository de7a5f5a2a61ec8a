package eu.brain.iot.federation.impl;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import eu.brain.iot.federation.impl.Wire.MalformedException;

/**
 * A node's membership in a fabric: announces what its behaviours consume, registers forwarders for what other nodes'
 * behaviours consume, carries forwarded events to those nodes with end-to-end acknowledgement, and delivers the
 * events other nodes send it. Free of OSGi: {@link FabricComponent} runs it in a framework, tests with the bus core.
 * <p>
 * Threads and what they own:
 * <ul>
 * <li>Paho's callback thread: the batches of events for this node that pass every check ({@link DirectBatches}),
 * into the {@link Inboxes} (which it shares with the inbound thread under their monitor); it queues every other
 * message for the inbound thread;</li>
 * <li>{@code brain-iot-fabric-in} (one thread): every other received message (checked, then applied), the table of
 * {@link RemoteNode}s and their forwarders, the {@link FabricInstaller}'s questions and orders in flight, the
 * {@link Inboxes}' acknowledgements and the events the bus refused for a moment, the {@link Refusals} and this
 * node's own retained topics ({@link OwnTopics}), connection events, the resend check, giving up on the events kept
 * for a node gone for good ({@link GivingUp});</li>
 * <li>{@code brain-iot-fabric-out} (one thread, the {@link Sender}): writes the {@link Outbox}es' journals and when
 * this node was last connected ({@link LastConnected}), takes batches from the outboxes and publishes them;</li>
 * <li>publishers (on their own threads, when the outbox has room) and the bus's delivery workers call the
 * forwarders, which append to the outboxes (see there).</li>
 * </ul>
 */
public final class FabricNode implements AutoCloseable {

    /** How often unacknowledged events are checked against the resend timeout, as a share of it. */
    static final int RESEND_CHECKS_PER_TIMEOUT = 4;
    /** Back-off between first connection attempts. */
    static final long CONNECT_RETRY_MILLIS = 1000;

    private final Settings settings;
    private final FabricKey key;
    private final Host host;
    private final Wire wire = new Wire();
    private final Topics topics;
    private final MqttLink link;
    private final ScheduledExecutorService in;
    private final Sender sender;
    private final FabricInstaller installer;

    private final Map<String, RemoteNode> nodes = new ConcurrentHashMap<>();
    private final Membership membership;
    private final Map<String, Outbox> outboxes = new ConcurrentHashMap<>();
    private final Inboxes inboxes;
    private final DirectBatches direct;
    private final GivingUp givingUp;
    private final Refusals refusals;
    private final OwnTopics ownTopics;
    private final LastConnected lastConnected;
    private volatile List<InterestEntry> localInterest = List.of();
    private volatile boolean closed;
    private volatile boolean joined;
    /** Inbound thread only: a connection attempt is scheduled; the broker's unreachability was logged (until the
     *  next connection); the node was connected before. */
    private boolean connecting;
    private boolean warnedUnreachable;
    /** Whether the clean start of this absence was logged (the inbound thread only). */
    private boolean toldCleanStart;
    private boolean joinedBefore;

    /**
     * @throws IOException when the key cannot be read or the state folder not used: the node does not join
     */
    public FabricNode(Settings settings, Host host) throws IOException {
        this.settings = settings;
        this.host = host;
        this.key = FabricKey.read(settings.keyFile());
        this.topics = new Topics(settings.fabric());
        Files.createDirectories(settings.stateDir());
        this.lastConnected = new LastConnected(settings.stateDir(), settings.offlineGiveUpMillis());
        openOutboxes();
        this.in = Executors.newSingleThreadScheduledExecutor(r -> new Thread(r, "brain-iot-fabric-in"));
        String self = settings.node();
        this.link = new MqttLink(settings, key, topics.status(self),
                since -> wire.status(new Wire.Status(self, Wire.Status.OFFLINE, System.currentTimeMillis(), since)),
                new MqttLink.Listener() {
                    @Override
                    public void connected() {
                        in.execute(FabricNode.this::onConnected);
                    }

                    @Override
                    public void disconnected(String why) {
                        if (!closed) {
                            host.warn("Fabric {}: node {} lost the broker {} ({}); reconnecting", settings.fabric(),
                                    self, settings.brokerUri(), why);
                            in.execute(FabricNode.this::connectOnce);
                        }
                    }

                    @Override
                    public void message(String topic, byte[] payload, String signature) {
                        long at = System.currentTimeMillis(); // both paths judge a message's age alike
                        if (closed || direct.took(topic, payload, signature, at)) {
                            return; // once closed, what was not acknowledged is sent again after a restart
                        }
                        in.execute(() -> onMessage(topic, payload, signature, at));
                    }
                });
        this.refusals = new Refusals(settings, host, System::currentTimeMillis);
        this.ownTopics = new OwnTopics(key, refusals, in, System::currentTimeMillis, this::republish);
        this.givingUp = new GivingUp(settings, host, wire, in, this::node, outboxes);
        this.membership = new Membership(settings.fabric(), host, in, () -> link.isConnected() ? link.since() : -1,
                this::node, this::outbox, d -> new ToNode(d, this::outbox, outboxes::get, wire, this::wakeSender),
                givingUp::wentOffline);
        this.sender = new Sender(settings, wire, topics, link, outboxes.values(), this::node, host, lastConnected);
        this.inboxes = new Inboxes(settings, host, wire, topics, link, in);
        this.direct = new DirectBatches(settings, key, topics, wire, refusals, inboxes, this::node,
                this::warnStateNotWritten);
        this.installer = new FabricInstaller(settings, in, new FabricInstaller.Sending() {
            @Override
            public void send(String to, Wire.Install message) throws IOException, InterruptedException {
                link.publish(topics.install(to, self), wire.install(message), false);
            }

            @Override
            public boolean joined() {
                return FabricNode.this.joined();
            }
        }, nodes::values, this::node, host);
    }

    /** Start: connect (retrying until the broker answers), then send. Never waits for the broker. */
    public void start() {
        sender.start();
        in.execute(this::connectOnce);
        long period = Math.max(10, settings.resendTimeoutMillis() / RESEND_CHECKS_PER_TIMEOUT);
        in.scheduleWithFixedDelay(() -> sender.resendCheck(false), period, period, TimeUnit.MILLISECONDS);
    }

    private void connectOnce() {
        if (closed || link.isConnected() || connecting) {
            return;
        }
        try {
            long now = System.currentTimeMillis();
            boolean clean = lastConnected.cleanStart(now);
            if (clean && !toldCleanStart) {
                toldCleanStart = true; // once per absence, not at every attempt while the broker cannot be reached
                host.info("Fabric {}: node {} was away for {} ms, over half of offline.giveup.ms: it joins with a "
                        + "clean broker session (its peers send again what they keep for it)", settings.fabric(),
                        settings.node(), lastConnected.awayMillis(now));
            }
            link.connect(clean); // connectComplete follows on Paho's thread
        } catch (IOException | RuntimeException | Error e) {
            if (!warnedUnreachable) {
                host.warn("Fabric {}: node {} cannot reach the broker: {}; trying again every {} ms",
                        settings.fabric(), settings.node(), e instanceof IOException ? e.getMessage() : e.toString(),
                        CONNECT_RETRY_MILLIS);
                warnedUnreachable = true;
            }
            connecting = true;
            in.schedule(() -> {
                connecting = false;
                connectOnce();
            }, CONNECT_RETRY_MILLIS, TimeUnit.MILLISECONDS);
        }
    }

    private void openOutboxes() throws IOException {
        Path dir = settings.stateDir().resolve("outbox");
        if (!Files.isDirectory(dir)) {
            return;
        }
        try (Stream<Path> files = Files.list(dir)) {
            for (Path f : files.filter(p -> p.getFileName().toString().endsWith(".journal")).toList()) {
                String node = f.getFileName().toString().replaceFirst("\\.journal$", "");
                if (Settings.NAME.matcher(node).matches()) {
                    outbox(node);
                }
            }
        }
    }

    Outbox outbox(String destination) {
        return outboxes.computeIfAbsent(destination, d -> {
            try {
                return new Outbox(d, settings.stateDir().resolve("outbox").resolve(d + ".journal"),
                        settings.maxPending(), node(d).stats);
            } catch (IOException e) {
                throw new IllegalStateException("the fabric journal for node " + d + " cannot be opened in "
                        + settings.stateDir() + ": " + e.getMessage(), e);
            }
        });
    }

    private void wakeSender() {
        sender.wake();
    }

    RemoteNode node(String name) {
        return nodes.computeIfAbsent(name, RemoteNode::new);
    }

    // ---- connection ------------------------------------------------------------------------------------------

    private void onConnected() {
        warnedUnreachable = false;
        toldCleanStart = false;
        boolean again = joinedBefore;
        joinedBefore = true;
        try {
            link.subscribe(topics.subscriptions(settings.node()));
            // the interest before the presence: a node that sees this one come back routes by its fresh interest,
            // never by the one retained from before (a behaviour may not be back yet; what it took stays held)
            publishInterest();
            publishPresence(Wire.Status.ONLINE);
            joined = true;
            if (!again) {
                in.schedule(refusals::checkAlone, Refusals.ALONE_AFTER_MILLIS, TimeUnit.MILLISECONDS);
            }
            host.info("Fabric {}: node {} joined through {}{}", settings.fabric(), settings.node(),
                    settings.brokerUri(), again ? " again" : "");
        } catch (IOException | InterruptedException e) {
            host.warn("Fabric {}: node {} could not announce itself: {}", settings.fabric(), settings.node(),
                    e.getMessage());
        }
        sender.resendCheck(true); // what the broker may have lost is sent again
        inboxes.flushAcks();
    }

    private void publishPresence(String state) throws IOException, InterruptedException {
        String self = settings.node();
        link.publish(topics.status(self), wire.status(new Wire.Status(self, state, System.currentTimeMillis(),
                link.since())),
                true);
    }

    private void publishInterest() throws IOException, InterruptedException {
        String self = settings.node();
        link.publish(topics.interest(self),
                wire.interest(new Wire.Interest(self, System.currentTimeMillis(), localInterest)), true);
    }

    /** What this node's behaviours consume now; announced at once when connected. */
    public void localInterest(Collection<InterestEntry> entries) {
        List<InterestEntry> sorted = entries.stream().distinct()
                .sorted((a, b) -> (a.types() + "|" + a.filter()).compareTo(b.types() + "|" + b.filter())).toList();
        localInterest = sorted;
        in.execute(() -> {
            if (link.isConnected()) {
                try {
                    publishInterest();
                } catch (IOException | InterruptedException e) {
                    host.warn("Fabric {}: the interest of node {} was not announced ({}); it is at the next "
                            + "connection", settings.fabric(), settings.node(), e.getMessage());
                }
            }
        });
    }

    // ---- received messages -----------------------------------------------------------------------------------

    /** @param at when the message arrived (epoch milliseconds), against which its age is judged */
    private void onMessage(String topic, byte[] payload, String signature, long at) {
        Topics.Parsed t = topics.parse(topic);
        if (t == null) {
            return;
        }
        boolean own = t.node().equals(settings.node());
        if (own && (Topics.INTEREST.equals(t.kind()) || Topics.STATUS.equals(t.kind()))) {
            ownTopics.received(topic, t.kind(), payload, signature);
            return;
        }
        String claimed = own ? t.other() : t.node();
        if (claimed == null || !Settings.NAME.matcher(claimed).matches()) {
            return;
        }
        RemoteNode known = nodes.get(claimed); // a refused message never adds a node
        // an empty one (a retained message removed) included: a node gone is told by its signed status instead
        Refusals.Reason refused = Refusals.check(key, topic, payload, signature);
        if (refused != null) {
            refusals.refused(topic, claimed, refused, null, known);
            return;
        }
        refusals.verified();
        NodeStats stats = node(claimed).stats;
        try {
            switch (t.kind()) {
            case Topics.EVENTS -> onBatch(claimed, wire.readBatch(payload), stats, topic, at);
            case Topics.ACKS -> onAck(claimed, wire.readAck(payload), stats, topic, at);
            case Topics.INTEREST -> {
                membership.onInterest(claimed, wire.readInterest(payload), stats);
                installer.membershipChanged(claimed); // after the forwarders: an install waiting for them ends
            }
            case Topics.STATUS -> membership.onStatus(claimed, wire.readStatus(payload), stats, () -> {
                installer.membershipChanged(claimed);
                sender.wake(); // a node back online: what was kept for it goes now
            });
            case Topics.INSTALL -> onInstall(claimed, wire.readInstall(payload), stats, topic, at);
            default -> refusals.refused(topic, claimed, Refusals.Reason.MALFORMED, "no such topic", node(claimed));
            }
        } catch (MalformedException e) {
            refusals.refused(topic, claimed, Refusals.Reason.MALFORMED, e.getMessage(), node(claimed));
        } catch (IOException e) {
            warnStateNotWritten(e);
        }
    }

    /** Publishes this node's own retained message of one kind again (a refused one stood in for it). */
    private void republish(String kind) {
        if (closed || !link.isConnected()) {
            return; // announced anew at the next connection
        }
        try {
            if (Topics.STATUS.equals(kind)) {
                publishPresence(Wire.Status.ONLINE);
            } else {
                publishInterest();
            }
        } catch (IOException | InterruptedException e) {
            host.warn("Fabric {}: node {} could not publish its {} again ({}); it does at its next connection",
                    settings.fabric(), settings.node(), kind, e.getMessage());
        }
    }

    private void warnStateNotWritten(Exception e) {
        host.warn("Fabric {}: the state of node {} cannot be written in {}: {}", settings.fabric(), settings.node(),
                settings.stateDir(), e.getMessage());
    }

    private boolean fresh(String from, long sent, String topic, long at) {
        long age = at - sent;
        if (!settings.inTime(sent, at)) {
            refusals.refused(topic, from, Refusals.Reason.REPLAYED,
                    age > 0 ? age + " ms ago" : -age + " ms ahead", nodes.get(from));
            return false;
        }
        return true;
    }

    private void onBatch(String from, Wire.Batch batch, NodeStats stats, String topic, long at) throws IOException {
        if (!batch.from().equals(from) || !batch.to().equals(settings.node())) {
            stats.malformed.increment();
            return;
        }
        if (!fresh(from, batch.sent(), topic, at)) {
            return;
        }
        inboxes.accept(from, batch, stats);
    }

    private void onInstall(String from, Wire.Install message, NodeStats stats, String topic, long at) {
        if (!message.from().equals(from) || !message.to().equals(settings.node())) {
            stats.malformed.increment();
        } else if (fresh(from, message.sent(), topic, at)) {
            installer.received(message);
        }
    }

    private void onAck(String from, Wire.Ack ack, NodeStats stats, String topic, long at) throws IOException {
        if (!ack.from().equals(from) || !ack.to().equals(settings.node())) {
            stats.malformed.increment();
            return;
        }
        if (!fresh(from, ack.sent(), topic, at)) {
            return;
        }
        Outbox outbox = outboxes.get(from);
        if (outbox != null) {
            outbox.acked(ack.epoch(), ack.through());
        }
    }

    // ---- views ------------------------------------------------------------------------------------------------

    /**
     * @return the fabric's installer: it asks the online nodes which one installs a behaviour, and has it installed
     *         there (see {@link FabricInstaller})
     */
    public eu.brain.iot.bis.api.BundleInstaller installer() {
        return installer;
    }

    /** This node's own installer, which the fabric's wraps and answers other nodes from; {@code null} for none. */
    public void localInstaller(eu.brain.iot.bis.api.BundleInstaller local) {
        installer.local(local);
    }

    /** @return whether the node is connected to the broker and announced */
    public boolean joined() {
        return joined && link.isConnected();
    }

    public String name() {
        return settings.node();
    }

    public Settings settings() {
        return settings;
    }

    /** One line per known node: its name, presence and interest. */
    public record NodeView(String node, String status, List<InterestEntry> interest, NodeStats.Snapshot stats) {
    }

    public List<NodeView> nodes() {
        Map<String, NodeView> views = new TreeMap<>();
        String mine = joined() ? "online (this node)" : "joining (this node)";
        views.put(settings.node(), new NodeView(settings.node(), mine,
                localInterest, new NodeStats().snapshot()));
        nodes.values().forEach(n -> views.put(n.name, new NodeView(n.name, n.status.name().toLowerCase(),
                n.interest, n.stats.snapshot())));
        return new ArrayList<>(views.values());
    }

    /** @return the messages refused from names this node knows as no node, and on its own topics */
    public NodeStats.Snapshot unverified() {
        return refusals.unverified.snapshot();
    }

    /** Leave the fabric: announce offline, disconnect normally, keep unacknowledged events in the journals. */
    @Override
    public void close() {
        closed = true;
        try {
            in.submit(() -> {
                installer.close();
                membership.leaveAll(nodes.values());
                if (link.isConnected()) {
                    try {
                        publishPresence(Wire.Status.OFFLINE);
                    } catch (IOException | InterruptedException e) {
                        // the broker sends the Last Will instead
                    }
                }
            }).get(10, TimeUnit.SECONDS);
        } catch (Exception e) {
            host.warn("Fabric {}: node {} left without announcing it ({})", settings.fabric(), settings.node(),
                    e.getMessage());
        }
        shutdown(false);
    }

    /** Stop as a crash would: no offline announcement, no normal disconnection (the broker sends the Last Will). */
    public void crash() {
        closed = true;
        shutdown(true);
    }

    private void shutdown(boolean abort) {
        inboxes.close(); // first: no window moves after this instant
        in.shutdownNow();
        try {
            in.awaitTermination(5, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        sender.close();
        if (abort) {
            link.abort();
        } else {
            link.close();
        }
        for (Outbox o : outboxes.values()) {
            try {
                o.close();
            } catch (IOException e) {
                host.warn("Fabric {}: journal for {} not closed: {}", settings.fabric(), o.destination(),
                        e.getMessage());
            }
        }
    }
}
