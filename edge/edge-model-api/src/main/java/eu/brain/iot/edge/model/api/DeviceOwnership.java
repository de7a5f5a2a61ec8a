package eu.brain.iot.edge.model.api;

import java.util.Set;

import org.osgi.annotation.versioning.ProviderType;

/**
 * Which devices of the fleet (robots, doors) this node's edge owns: it polls those, holds them in its
 * {@link DeviceModel} and sends them commands; the others it leaves to other nodes. The configuration of the edge
 * gives the first share (by default every device); a lease manager moves devices between nodes at run time, without
 * a restart: a device taken is polled at once and announced as on discovery (its position, with no previous cell),
 * a device released leaves the model with a {@code DeviceRemoved} event and is commanded no more. Registered by the
 * edge beside its {@link DeviceModel}. Thread-safe. Since 1.2.
 */
@ProviderType
public interface DeviceOwnership {

    /** @return the name this node gives itself on every command it sends ({@code fabric.node.name}) */
    String nodeName();

    /**
     * @return the ids of the fleet's devices this node owns: its share and what it took, less what it released;
     *         only devices the fleet is known to have (its inventory, or the configured {@code robots} and
     *         {@code doors}), so empty until the fleet answered
     */
    Set<String> owned();

    /**
     * @return the ids of the fleet's devices this node's configuration gives it (its share), whatever was taken or
     *         released since; empty until the fleet answered. Since 1.3.
     */
    Set<String> share();

    /** @return the ids of every device of the fleet, owned or not; empty until the fleet answered. Since 1.3. */
    Set<String> fleet();

    /** @return whether this node owns the device (taken or in its share, and not released) */
    boolean owns(String deviceId);

    /**
     * Takes these devices over: they are polled at once (a device the fleet does not have yet is polled once the
     * fleet lists it). Taking an owned device changes nothing.
     *
     * @param deviceIds device ids (letters, digits, '_', '.' or '-')
     * @return the ids this node did not own before
     * @throws IllegalArgumentException naming an id that is no device id
     */
    Set<String> take(Set<String> deviceIds);

    /**
     * Lets these devices go: they leave the model (the bus hears {@code DeviceRemoved}) and are neither polled nor
     * commanded by this node any more. Releasing a device not owned changes nothing.
     *
     * @param deviceIds device ids (letters, digits, '_', '.' or '-')
     * @return the ids this node owned before
     * @throws IllegalArgumentException naming an id that is no device id
     */
    Set<String> release(Set<String> deviceIds);

    /**
     * Whether the device, owned by this node, may change hands now without interrupting anything: a device changing
     * hands is neither polled nor commanded for a while (the lease manager's rule), so a lease manager hands a device
     * at rest over first and the others one at a time. Since 1.4.
     *
     * @return whether this node owns the device, has polled it lately, and it rests: a robot idle in the docking
     *         area, carrying nothing; a door closed. {@code false} by default (nothing known to be at rest)
     */
    default boolean atRest(String deviceId) {
        return false;
    }
}
