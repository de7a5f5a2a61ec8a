/**
 * The service provider interface between the event bus and the Behaviour Management Service: what happens to an
 * event that no behaviour consumes. Behaviours never use this package; only a management service that installs
 * behaviours on demand does.
 * <p>
 * Why a synchronous policy and a hold inside the bus, rather than a consumer of last resort that keeps events
 * itself: a consumer of last resort receives its events asynchronously, so by the time it has installed the
 * behaviour, newer events published straight to that behaviour could overtake the older ones still waiting in
 * the consumer's queue. Here the bus asks the policy on the publisher's thread, keeps held events in one queue in
 * publish order, and hands them to a new behaviour in the same step that makes it visible to publishers: no held
 * event is overtaken, lost or delivered twice.
 * <p>
 * Since 1.1 the package also joins a node to a fabric of nodes: an {@link eu.brain.iot.eventing.spi.EventForwarder}
 * takes events for the behaviours of another node, routed by the bus like a behaviour, and
 * {@link eu.brain.iot.eventing.spi.RemoteEvents} delivers events from other nodes to the local behaviours only.
 */
@Export
@Version("1.5.0")
package eu.brain.iot.eventing.spi;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
