package eu.brain.iot.federation.impl;

import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;

import eu.brain.iot.edge.model.api.DeviceOwnership;

/**
 * Tells the fabric's installer which devices this node's edge owns (the edge's {@link DeviceOwnership}), so that
 * this node's install offers say which of the devices an event names it owns ({@link InstallChoice}). Active only on
 * a node with both the fabric's configuration and an edge; a node without an edge owns none. A component apart from
 * {@link FabricComponent} because the edge's package is an optional import: this class is loaded only once an edge
 * registered its ownership.
 * <p>
 * Threads: SCR activates and deactivates it; the fabric's inbound thread then asks the edge's ownership
 * (thread-safe, from memory).
 */
@Component(immediate = true)
public final class EdgeOwnedDevices {

    private final FabricComponent fabric;

    @Activate
    public EdgeOwnedDevices(@Reference FabricComponent fabric, @Reference DeviceOwnership ownership) {
        this.fabric = fabric;
        fabric.ownedDevices(ownership::owns);
    }

    @Deactivate
    void deactivate() {
        fabric.ownedDevices(null);
    }
}
