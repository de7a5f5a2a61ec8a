package eu.brain.iot.federation.impl;

/**
 * The fabric's topic tree, under {@code brainiot/<fabric>/nodes/<node>/}: {@code interest} and {@code status}
 * (retained), {@code events/<from>} (batches of events for the node, from a publisher) and {@code acks/<from>}
 * (acknowledgements for the node, from a receiver), {@code install/<from>} (which node installs a behaviour: bids,
 * offers, orders, results, for the node from another).
 */
final class Topics {

    static final String ROOT = "brainiot";
    static final String INTEREST = "interest";
    static final String STATUS = "status";
    static final String EVENTS = "events";
    static final String ACKS = "acks";
    static final String INSTALL = "install";

    private final String base;

    Topics(String fabric) {
        this.base = ROOT + "/" + fabric + "/nodes/";
    }

    String interest(String node) {
        return base + node + "/" + INTEREST;
    }

    String status(String node) {
        return base + node + "/" + STATUS;
    }

    String events(String to, String from) {
        return base + to + "/" + EVENTS + "/" + from;
    }

    String acks(String to, String from) {
        return base + to + "/" + ACKS + "/" + from;
    }

    /** Questions and answers about installing behaviours, for {@code to} from {@code from} (see FabricInstaller). */
    String install(String to, String from) {
        return base + to + "/" + INSTALL + "/" + from;
    }

    /** The subscriptions of a node. */
    String[] subscriptions(String self) {
        return new String[] { base + self + "/" + EVENTS + "/+", base + self + "/" + ACKS + "/+",
                base + self + "/" + INSTALL + "/+",
                base + "+/" + INTEREST, base + "+/" + STATUS };
    }

    /** A parsed topic of this fabric: the node it is under, its kind, and the other node named after it, if any. */
    record Parsed(String node, String kind, String other) {
    }

    /** @return the parsed topic, or {@code null} if it is not one of this fabric's */
    Parsed parse(String topic) {
        if (!topic.startsWith(base)) {
            return null;
        }
        String[] parts = topic.substring(base.length()).split("/", -1);
        if (parts.length == 2) {
            return new Parsed(parts[0], parts[1], null);
        }
        if (parts.length == 3) {
            return new Parsed(parts[0], parts[1], parts[2]);
        }
        return null;
    }
}
