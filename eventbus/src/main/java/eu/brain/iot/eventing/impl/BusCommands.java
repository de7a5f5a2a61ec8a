package eu.brain.iot.eventing.impl;

import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;

import eu.brain.iot.eventing.monitoring.api.ConsumerStatistics;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;
import eu.brain.iot.eventing.monitoring.api.EventTypeStatistics;

/** Gogo commands {@code bus:stats} and {@code bus:behaviours}. */
@Component(service = BusCommands.class, property = { "osgi.command.scope=bus", "osgi.command.function=stats",
        "osgi.command.function=behaviours" })
public final class BusCommands {

    private final EventBusStatistics statistics;

    @Activate
    public BusCommands(@Reference EventBusStatistics statistics) {
        this.statistics = statistics;
    }

    /** Counters per event type. */
    public String stats() {
        StringBuilder out = new StringBuilder(String.format("%-60s %12s %12s %8s %10s %10s%n", "EVENT TYPE",
                "PUBLISHED", "DELIVERED", "FAILED", "UNHANDLED", "DISCARDED"));
        for (EventTypeStatistics s : statistics.eventTypes()) {
            out.append(String.format("%-60s %12d %12d %8d %10d %10d%n", s.eventType, s.published, s.delivered,
                    s.failed, s.unhandled, s.discarded));
        }
        return out.append(behaviours()).toString();
    }

    /** The registered smart behaviours with their queues. */
    public String behaviours() {
        StringBuilder out = new StringBuilder(String.format("%-40s %-32s %8s %12s %8s  %s%n", "BEHAVIOUR", "BUNDLE",
                "QUEUED", "DELIVERED", "FAILED", "CONSUMES"));
        for (ConsumerStatistics c : statistics.consumers()) {
            String consumes = c.lastResort ? "(last resort: unhandled events)" : String.join(",", c.consumed);
            if (!c.filter.isEmpty()) {
                consumes += " where " + c.filter;
            }
            out.append(String.format("%-40s %-32s %8d %12d %8d  %s%s%n", c.consumer, c.bundle, c.queueDepth,
                    c.delivered, c.failures, c.untyped ? "[untyped] " : "", consumes));
        }
        return out.toString();
    }
}
