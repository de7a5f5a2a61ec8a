package eu.brain.iot.federation.impl;

import java.util.Collection;
import java.util.Comparator;
import java.util.List;
import java.util.Objects;

import eu.brain.iot.bis.api.BehaviourCandidate;

/**
 * The rule by which the node that asked chooses which node installs a behaviour, among the answers it has (all
 * online nodes', or those in by the deadline; its own always): only nodes whose installer offers a candidate count;
 * then the node that owns the most of the devices the event names ({@link DeviceNames}: its behaviour then runs
 * beside the edge that polls and commands them); then a node other than the one that asked (the event's publisher
 * runs there: a behaviour that answers another's events, as the orchestrator answers the offers of the robot
 * behaviour that drives the fleet, which name no device, does not die with it, and is there for the one that takes
 * over); then the lowest load (behaviours its installer installed); then the lowest node name, so that every run of
 * the same answers gives the same choice. Each node says in its offer which of the named devices it owns; a node
 * that does not say (an older one) owns none.
 * <p>
 * Stateless.
 */
final class InstallChoice {

    /**
     * One node's answer: the candidates its installer offers (best first), its load, and which of the devices the
     * event names it owns.
     */
    record Offer(String node, List<BehaviourCandidate> candidates, int load, List<String> owns) {

        Offer {
            owns = owns == null ? List.of() : owns.stream().filter(Objects::nonNull).distinct().toList();
        }

        /** An offer that owns none of the devices named. */
        Offer(String node, List<BehaviourCandidate> candidates, int load) {
            this(node, candidates, load, List.of());
        }

        boolean offers() {
            return candidates != null && !candidates.isEmpty();
        }
    }

    private InstallChoice() {
    }

    /** @return the rule's order of the offers to a bid the node {@code asker} sent, best first */
    static Comparator<Offer> order(String asker) {
        return Comparator.comparingInt((Offer o) -> o.owns().size()).reversed()
                .thenComparing((Offer o) -> o.node().equals(asker)).thenComparingInt(Offer::load)
                .thenComparing(Offer::node);
    }

    /** @return the chosen node's offer, or {@code null} when no node offers a candidate */
    static Offer choose(Collection<Offer> offers, String asker) {
        return offers.stream().filter(Offer::offers).min(order(asker)).orElse(null);
    }
}
