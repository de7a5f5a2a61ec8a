package eu.brain.iot.federation.impl;

import java.util.EnumSet;
import java.util.HashMap;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.LongSupplier;
import java.util.function.Supplier;

/**
 * The messages this node refuses: counted, and told to the operator in WARN lines that say what was refused, from
 * which node, why and what to do, without letting a flood of refusals flood the log.
 * <p>
 * Counting: a refusal from a node this node knows (it has verified a message of it before, or keeps events for it)
 * goes to that node's {@link NodeStats}; any other, whatever name it claims, goes to one total, {@link #unverified},
 * so that a client of the broker without the key cannot add names to the table of nodes.
 * <p>
 * Logging, per claimed node (per topic for this node's own): the first refusal of each reason at once, then at most
 * one line every {@link #REPEAT_MILLIS} with the number refused since the last line. At most
 * {@link #MAX_TRACKED_NAMES} unverified names are followed one by one; beyond them they share one line's limit.
 * <p>
 * Alone: when this node has verified no message of any other node {@link #ALONE_AFTER_MILLIS} after it joined, but
 * refused some with a signature that does not match its key, it says once that its own key is most likely not the
 * fabric's.
 * <p>
 * Threads: the fabric's inbound thread calls every method but {@link #verified} (Paho's callback thread too) and the
 * counters' readers; the counters are adders, read by the commands on any thread.
 */
final class Refusals {

    /** Why a message was refused. */
    enum Reason { UNSIGNED, BAD_SIGNATURE, REPLAYED, MALFORMED, REMOVED }

    /** Least time between two log lines about refusals from one node, after the first of each reason. */
    static final long REPEAT_MILLIS = 60_000;
    /** Unverified names followed one by one; more share {@link #OTHER_NAMES}. */
    static final int MAX_TRACKED_NAMES = 16;
    /** The key of the names beyond {@link #MAX_TRACKED_NAMES}. */
    static final String OTHER_NAMES = "(other unverified names)";
    /** How long after joining a node that heard only refused messages from other nodes says so. */
    static final long ALONE_AFTER_MILLIS = 5_000;

    private static final long MILLIS_PER_SECOND = 1000;
    /** Most characters of a parser's complaint quoted in a log line (it may quote the payload). */
    static final int MAX_DETAIL_CHARS = 200;
    /** Refusals of messages from names no verified message came from (node names cannot hold parentheses). */
    static final String UNVERIFIED = "(unverified)";

    private final Settings settings;
    private final Host host;
    private final LongSupplier clock;
    /** Refusals from names not known as nodes of the fabric, and of messages on this node's own topics. */
    final NodeStats unverified = new NodeStats();
    private final Map<String, Followed> followed = new HashMap<>();
    private int unverifiedFollowed;
    /**
     * Whether a message of another node passed the signature check since this node started (set by Paho's callback
     * thread too, for the batches of events it takes).
     */
    private volatile boolean heardVerified;
    /** Names whose messages had a signature this node's key does not match. */
    private final Set<String> badSignatureFrom = new TreeSet<>();
    private boolean toldAlone;

    /** What was logged about one claimed name. */
    private static final class Followed {
        final Set<Reason> told = EnumSet.noneOf(Reason.class);
        /** When the last line about it was logged. */
        long lastLine;
        /** Refusals from it since, that no line told. */
        long untold;
    }

    /** @param clock milliseconds since the epoch */
    Refusals(Settings settings, Host host, LongSupplier clock) {
        this.settings = settings;
        this.host = host;
        this.clock = clock;
    }

    /**
     * Why a received message is refused, the one check every received message passes before anything of it is
     * applied: an empty payload (it removes a retained message) always, since no node of a fabric publishes one, so
     * none is ever signed by a member; otherwise no signature, or one that does not match the fabric's key.
     *
     * @return {@code null} when the message is to be applied
     */
    static Reason check(FabricKey key, String topic, byte[] payload, String signature) {
        if (payload.length == 0) {
            return Reason.REMOVED;
        }
        if (signature == null) {
            return Reason.UNSIGNED;
        }
        return key.verify(topic, payload, signature) ? null : Reason.BAD_SIGNATURE;
    }

    /** A message of another node passed the signature check. */
    void verified() {
        heardVerified = true;
    }

    /**
     * A message from another node refused: counted in {@code known}'s stats, or in {@link #unverified}, and logged.
     *
     * @param known the node as this node knows it, {@code null} when no verified message came from that name
     * @param detail what was wrong, for a malformed or replayed message; {@code null} otherwise
     */
    void refused(String topic, String claimed, Reason reason, String detail, RemoteNode known) {
        NodeStats stats = known != null ? known.stats : unverified;
        count(stats, reason);
        if (reason == Reason.BAD_SIGNATURE) {
            badSignatureFrom.add(claimed);
        }
        log(known != null, claimed, reason, () -> String.format("Fabric %s: node %s refused a message on %s "
                + "claiming to come from node %s: %s (counted in fabric:stats as %s, row %s)", settings.fabric(),
                settings.node(), topic, claimed, why(reason, detail), column(reason),
                known != null ? claimed : UNVERIFIED));
    }

    /**
     * A message on one of this node's own retained topics that this node did not sign: counted in
     * {@link #unverified} and logged; the caller publishes its own again.
     */
    void refusedOwn(String topic, Reason reason) {
        count(unverified, reason);
        log(true, topic, reason, () -> String.format("Fabric %s: node %s refused a message on its own "
                + "retained topic %s: %s. The broker held it in place of this node's own, which hides this node "
                + "from the nodes that start later: this node publishes its own again. A client of the broker "
                + "publishes on this fabric's topics: find it and stop it, or give the broker access rules",
                settings.fabric(), settings.node(), topic, why(reason, null)));
    }

    /** Once, {@link #ALONE_AFTER_MILLIS} after joining: says when every other node's messages were refused. */
    void checkAlone() {
        if (toldAlone || heardVerified || badSignatureFrom.isEmpty()) {
            return;
        }
        toldAlone = true;
        host.warn("Fabric {}: node {} has refused every message of the other nodes ({}) since it joined {} ms ago, "
                + "their signatures not matching its key: this node's key file {} is most likely not the fabric's "
                + "key. Copy the key file of the fabric's other nodes here (federation/README.md, \"Trust\") and "
                + "start this node again", settings.fabric(), settings.node(), String.join(", ", badSignatureFrom),
                ALONE_AFTER_MILLIS, settings.keyFile());
    }

    private static void count(NodeStats stats, Reason reason) {
        switch (reason) {
        case UNSIGNED, REMOVED -> stats.unsigned.increment();
        case BAD_SIGNATURE -> stats.badSignature.increment();
        case REPLAYED -> stats.replayed.increment();
        case MALFORMED -> stats.malformed.increment();
        }
    }

    private void log(boolean verifiedName, String claimed, Reason reason, Supplier<String> line) {
        String key = claimed;
        if (!followed.containsKey(claimed) && !verifiedName) {
            if (unverifiedFollowed >= MAX_TRACKED_NAMES) {
                key = OTHER_NAMES;
            } else {
                unverifiedFollowed++;
            }
        }
        Followed f = followed.computeIfAbsent(key, k -> new Followed());
        long now = clock.getAsLong();
        if (f.told.add(reason)) {
            host.warn("{}", line.get());
            f.lastLine = now;
            return;
        }
        f.untold++;
        if (now - f.lastLine >= REPEAT_MILLIS) {
            host.warn("{}; {} refused from {} in the last {} s without a line of their own (this one included)",
                    line.get(), f.untold, source(key), (now - f.lastLine) / MILLIS_PER_SECOND);
            f.lastLine = now;
            f.untold = 0;
        }
    }

    /** What a key of {@link #followed} names: a node, this node's own topic, or the names beyond the bound. */
    private static String source(String key) {
        if (key.equals(OTHER_NAMES)) {
            return "names beyond the first " + MAX_TRACKED_NAMES + " unverified ones";
        }
        return key.indexOf('/') >= 0 ? "this node's own topic " + key : "node " + key;
    }

    private String why(Reason reason, String detail) {
        return switch (reason) {
        case UNSIGNED -> "it carries no signature, so no node of this fabric published it (a client of the broker "
                + "without the fabric key did); nothing of it was applied";
        case BAD_SIGNATURE -> "its signature does not match this node's fabric key (" + settings.keyFile() + "); "
                + "nothing of it was applied. The sending node may use another fabric key: every node of a fabric "
                + "needs the same key file; federation/README.md (\"Trust\") says how to share it";
        case REPLAYED -> "it was signed " + detail + ", more than max.age.ms (" + settings.maxAgeMillis() + " ms) "
                + "from this node's clock: a replay, or the two nodes' clocks disagree (keep them in time with NTP)";
        case MALFORMED -> "it is not in the fabric's wire format (" + shortened(detail) + "): a node of another "
                + "build, or a client publishing by hand";
        case REMOVED -> "it removes the retained message (an empty payload), which no node of this fabric "
                + "publishes (a client of the broker without the fabric key did); nothing of it was applied";
        };
    }

    private static String shortened(String detail) {
        return detail == null || detail.length() <= MAX_DETAIL_CHARS ? detail
                : detail.substring(0, MAX_DETAIL_CHARS) + "...";
    }

    private static String column(Reason reason) {
        return switch (reason) {
        case UNSIGNED, REMOVED -> "UNSIGNED";
        case BAD_SIGNATURE -> "BAD-SIG";
        case REPLAYED -> "REPLAYED";
        case MALFORMED -> "REFUSED (malformed)";
        };
    }
}
