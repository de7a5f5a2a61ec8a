package eu.brain.iot.federation.impl;

import java.util.Collection;
import java.util.Comparator;
import java.util.List;

import eu.brain.iot.bis.api.BehaviourCandidate;

/**
 * The rule by which the node that asked chooses which node installs a behaviour, among the answers it has (all
 * online nodes', or those in by the deadline; its own always): only nodes whose installer offers a candidate count;
 * then the lowest load (behaviours its installer installed); then the lowest node name, so that every run of the
 * same answers gives the same choice. Ownership of the devices an event names is not a criterion: no node knows
 * cheaply which devices another node owns (nothing in the fabric announces it), so it is left out rather than guessed.
 * <p>
 * Stateless.
 */
final class InstallChoice {

    /** One node's answer: the candidates its installer offers (best first), and its load. */
    record Offer(String node, List<BehaviourCandidate> candidates, int load) {
    }

    static final Comparator<Offer> ORDER = Comparator.comparingInt(Offer::load).thenComparing(Offer::node);

    private InstallChoice() {
    }

    /** @return the chosen node's offer, or {@code null} when no node offers a candidate */
    static Offer choose(Collection<Offer> offers) {
        return offers.stream().filter(o -> o.candidates() != null && !o.candidates().isEmpty()).min(ORDER)
                .orElse(null);
    }
}
