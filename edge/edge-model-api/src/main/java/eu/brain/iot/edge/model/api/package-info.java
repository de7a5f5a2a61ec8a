/**
 * The edge's device model in the sensiNact manner: providers (a robot, a door) hold services ({@code position},
 * {@code state}, {@code cart}, {@code mission}, {@code door}, ...) that hold resources ({@code x}, {@code y},
 * {@code state}, {@code detect}, ...), each with a value, a timestamp and a status. Read it, subscribe to its
 * changes, and act on devices through {@link eu.brain.iot.edge.model.api.DeviceModel}. Since 1.1, the polling and
 * publishing counters ({@link eu.brain.iot.edge.model.api.PollMonitor}). Besides robots and doors, the model holds
 * what the edge reads from the fleet's world (kind {@code cart}: providers {@code cart1}, ... with {@code position.x},
 * {@code position.y}, {@code cart.carriedBy}; kind {@code warehouse}: provider {@code warehouse} with
 * {@code map.name}, {@code map.width}, {@code map.height}, {@code map.rows}, the grid's rows joined by a newline).
 * Since 1.2, which devices this node owns, and their hand-over between nodes
 * ({@link eu.brain.iot.edge.model.api.DeviceOwnership}); since 1.4, whether a device may change hands without
 * interrupting anything, and one resource's value of a provider's snapshot.
 */
@Export
@Version("1.4.0")
package eu.brain.iot.edge.model.api;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
