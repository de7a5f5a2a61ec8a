package eu.brain.iot.federation.impl;

import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicyOption;

import eu.brain.iot.edge.model.api.DeviceOwnership;

/**
 * Tells the fabric's installer which devices this node's edge owns (the edge's {@link DeviceOwnership}), so that
 * this node's install offers say which of the devices an event names it owns ({@link InstallChoice}). Active on a node
 * with the fabric's configuration; without an edge (an optional reference, as for {@link LeaseManager}, so that the
 * bundle resolves without one) the node owns none, and an edge that comes later restarts it with its ownership.
 * <p>
 * Threads: SCR activates and deactivates it; the fabric's inbound thread then asks the edge's ownership
 * (thread-safe, from memory).
 */
@Component(immediate = true)
public final class EdgeOwnedDevices {

    private final FabricComponent fabric;

    @Activate
    public EdgeOwnedDevices(@Reference FabricComponent fabric,
            @Reference(cardinality = ReferenceCardinality.OPTIONAL, policyOption = ReferencePolicyOption.GREEDY)
            DeviceOwnership ownership) {
        this.fabric = fabric;
        fabric.ownedDevices(ownership == null ? null : ownership::owns);
    }

    @Deactivate
    void deactivate() {
        fabric.ownedDevices(null);
    }
}
