package eu.brain.iot.edge.model.api;

import java.time.Instant;

/**
 * One resource of one service of one provider, as the edge knows it now.
 *
 * @param provider  the provider (device) id, for example {@code robot1}
 * @param service   the service, for example {@code position}
 * @param resource  the resource, for example {@code x}
 * @param value     a String, Number or Boolean, or {@code null} (a robot that carries no cart)
 * @param timestamp when the value last changed (the poll that saw the change)
 * @param status    whether the value is current
 */
public record ResourceValue(String provider, String service, String resource, Object value, Instant timestamp,
        ResourceStatus status) {
}
