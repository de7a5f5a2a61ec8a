package eu.brain.iot.edge.model.api;

import java.time.Instant;
import java.util.List;
import java.util.Map;

/**
 * A provider (a robot or a door) at one moment: every resource by service, and the actions it accepts.
 *
 * @param id        the provider id, for example {@code robot1}
 * @param kind      {@code robot} or {@code door}
 * @param status    the status of its resources
 * @param lastPoll  when the device last answered a poll, {@code null} before the first answer
 * @param reason    why the status is not {@code OK} (the last failure), else {@code null}
 * @param services  resources by service name, then by resource name, in a stable order
 * @param actions   the actions by service name, with their parameters, for example {@code control -> [goTo(x,y), pick]}
 */
public record ProviderSnapshot(String id, String kind, ResourceStatus status, Instant lastPoll, String reason,
        Map<String, Map<String, ResourceValue>> services, Map<String, List<String>> actions) {

    /**
     * @return the value of one resource, for example {@code value("position", "x")}; {@code null} when the provider
     *         has no such service or resource, or no value for it yet. Since 1.4.
     */
    public Object value(String service, String resource) {
        Map<String, ResourceValue> resources = services.get(service);
        ResourceValue v = resources == null ? null : resources.get(resource);
        return v == null ? null : v.value();
    }
}
