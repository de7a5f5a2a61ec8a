package eu.brain.iot.eventing.impl;

import java.util.Arrays;
import java.util.List;
import java.util.Map;

import eu.brain.iot.eventing.impl.RouteTable.Route;

/**
 * Where an event goes that this node published for a node of the fabric that never took it, given up once that
 * node stayed offline (RemoteEvents#tryDeliverGivenUp): to every consumer of its type names, local behaviours and
 * forwarders to other nodes alike, registered after it was first published, which cannot have had it; when nothing
 * consumes it at all, the bus's path for unhandled events (the policy's hold). Consumers that were there before get
 * nothing: they had it, or their filter did not take it.
 * <p>
 * Keeps no state; runs on the caller's thread and never waits.
 */
final class GivenUp {

    private GivenUp() {
    }

    /**
     * @return false when a queue (or the hold) was full: nothing was queued; true otherwise, also when every consumer
     *         it has was there before
     */
    static boolean publish(AsyncEventBus bus, String eventType, List<String> typeNames, Map<String, Object> eventData,
            long publishedMillis) {
        if (eventType == null || eventType.isEmpty() || eventData == null) {
            throw new IllegalArgumentException("tryDeliverGivenUp: eventType and eventData are required, got "
                    + "eventType=" + eventType);
        }
        List<String> names = RouteTable.remoteNames(eventType, typeNames);
        Map<String, Object> snapshot = EventMaps.copyMap(eventData);
        RouteTable table = bus.settledRoutes();
        Route route = table.routeForGivenUp(eventType, names, bus::countersFor);
        ConsumerChannel[] targets = route.targets(snapshot);
        if (targets.length == 0) {
            // held as a local untyped event: the behaviour the BMS has installed for it may run on another node
            return bus.unhandled(table, route, snapshot, null, null, false, null);
        }
        ConsumerChannel[] since = Arrays.stream(targets).filter(c -> c.createdMillis > publishedMillis)
                .toArray(ConsumerChannel[]::new);
        return since.length == 0 || bus.send(since, route, snapshot, false, null);
    }
}
