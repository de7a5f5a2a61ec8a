package eu.brain.iot.edge.impl;

import java.util.Set;

import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceStatus;

/**
 * Which of its devices an edge may hand to another node without interrupting anything
 * ({@link eu.brain.iot.edge.model.api.DeviceOwnership#atRest}): a device changing hands is neither polled nor
 * commanded for a lease period and a quarter, so a robot handed over mid-errand stands still that long, where other
 * robots may come up behind it. At rest: a robot polled lately ({@code OK}), parked in the docking area (robot-sim's
 * area code 1), no mission queued or running, carrying no cart; a door polled lately and closed. Stateless: any
 * thread.
 */
final class Resting {

    /** robot-sim's area code of the docking area (its robot API's {@code area}). */
    static final int DOCKING_AREA = 1;
    /** Mission states of a robot with work to do. */
    private static final Set<String> BUSY = Set.of("queued", "running");
    private static final String CLOSED = "closed";

    private Resting() {
    }

    /** @return whether the device, as this node's model shows it, is at rest */
    static boolean atRest(ProviderSnapshot p) {
        if (p.status() != ResourceStatus.OK) {
            return false;
        }
        return switch (p.kind()) {
            case "robot" -> p.value("position", "area") instanceof Number area && area.intValue() == DOCKING_AREA
                    && !BUSY.contains(String.valueOf(p.value("mission", "state")))
                    && p.value("cart", "cart") == null;
            case "door" -> CLOSED.equals(p.value("door", "state"));
            default -> false;
        };
    }
}
