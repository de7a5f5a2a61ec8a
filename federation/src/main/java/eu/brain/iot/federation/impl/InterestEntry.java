package eu.brain.iot.federation.impl;

import java.util.List;

/**
 * What one behaviour consumes: its event types (supertypes and interfaces of an event match, as on the local bus) and
 * an LDAP filter over the event's fields, {@code null} for none.
 *
 * @param types the consumed event type names, sorted
 * @param filter the filter, or {@code null}
 */
public record InterestEntry(List<String> types, String filter) {

    public InterestEntry {
        types = types.stream().sorted().distinct().toList();
        filter = filter == null || filter.isBlank() ? null : filter;
    }
}
