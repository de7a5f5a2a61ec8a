package eu.brain.iot.federation.impl;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;

import eu.brain.iot.bis.api.BehaviourCandidate;
import eu.brain.iot.federation.impl.RemoteNode.Presence;

/**
 * The recovery step for behaviours on a node that went offline: its last interest stays known (the retained
 * announcement is not withdrawn by its Last Will nor by its goodbye), so when no node online offers a behaviour for
 * an event's types, the fabric's installer answers "the behaviour of that node" and its install waits for the node to
 * come back with that interest (up to {@code install.timeout.ms}). Meanwhile the BMS holds the events, and the bus
 * hands them over to the node's forwarder once it is back, in order: a node killed and started again misses nothing,
 * and one gone for good has its events re-decided by the BMS when the wait fails.
 * <p>
 * Stateless; reads the nodes' volatile presence and interest.
 */
final class Departed {

    private Departed() {
    }

    /** @return one candidate per offline node whose last interest takes one of the types, lowest name first */
    static List<BehaviourCandidate> candidates(Collection<RemoteNode> nodes, List<String> types) {
        List<BehaviourCandidate> out = new ArrayList<>();
        nodes.stream().filter(n -> n.status == Presence.OFFLINE && takes(n.interest, types))
                .sorted((a, b) -> a.name.compareTo(b.name)).forEach(n -> {
                    BehaviourCandidate c = new BehaviourCandidate();
                    c.symbolicName = behaviourOf(n.name);
                    c.version = BACK;
                    c.consumed = List.copyOf(types);
                    c.node = n.name;
                    out.add(c);
                });
        return out;
    }

    /** The name a departed node's behaviour goes by in the BMS's requests and history. */
    static String behaviourOf(String node) {
        return "node " + node + "'s behaviours";
    }

    /** The version a departed node's behaviour goes by: what its install waits for. */
    static final String BACK = "(once back online)";

    /** @return whether an entry of the interest consumes one of the types (no types: any interest) */
    static boolean takes(List<InterestEntry> interest, List<String> types) {
        if (types == null || types.isEmpty()) {
            return !interest.isEmpty();
        }
        return interest.stream().anyMatch(e -> e.types().stream().anyMatch(types::contains));
    }
}
