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
 * beside the edge that polls and commands them); then the lowest load (behaviours its installer installed); then
 * the lowest node name, so that every run of the same answers gives the same choice. Each node says in its offer
 * which of the named devices it owns; a node that does not say (an older one) owns none.
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

    static final Comparator<Offer> ORDER = Comparator.comparingInt((Offer o) -> o.owns().size()).reversed()
            .thenComparingInt(Offer::load).thenComparing(Offer::node);

    private InstallChoice() {
    }

    /** @return the chosen node's offer, or {@code null} when no node offers a candidate */
    static Offer choose(Collection<Offer> offers) {
        return offers.stream().filter(Offer::offers).min(ORDER).orElse(null);
    }
}
