package eu.brain.iot.eventing.impl;

import java.util.Map;

import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;

import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.EventBusOverflowException;
import eu.brain.iot.eventing.monitoring.api.ConsumerStatistics;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;
import eu.brain.iot.eventing.monitoring.api.EventTypeStatistics;

/** Gogo commands {@code bus:stats}, {@code bus:behaviours} and {@code bus:publish}. */
@Component(service = BusCommands.class, property = { "osgi.command.scope=bus", "osgi.command.function=stats",
        "osgi.command.function=behaviours", "osgi.command.function=publish" })
public final class BusCommands {

    static final String PUBLISH_USAGE = "usage: bus:publish TYPE key=value ... (values: 42, 1.5, true, "
            + "\"two words\"; nested: at.x=3), e.g. bus:publish "
            + "eu.brain.iot.behaviours.events.RobotBehaviorUnloadLocation component=Robot1 position=2 detect=0";

    private final EventBusStatistics statistics;
    private final EventBus bus;

    @Activate
    public BusCommands(@Reference EventBusStatistics statistics, @Reference EventBus bus) {
        this.statistics = statistics;
        this.bus = bus;
    }

    /**
     * Publish an untyped event by hand; typed behaviours that consume the type receive it converted to their
     * class. Errors come back as a message, not an exception: this is typed by a person.
     */
    public String publish(String eventType, String... fields) {
        if (eventType.contains("=")) {
            return "bus:publish: the event type comes first, got \"" + eventType + "\"; " + PUBLISH_USAGE;
        }
        Map<String, Object> data;
        try {
            data = EventArguments.parse(fields);
        } catch (IllegalArgumentException e) {
            return "bus:publish: " + e.getMessage() + "; " + PUBLISH_USAGE;
        }
        try {
            bus.deliver(eventType, data);
        } catch (EventBusOverflowException e) {
            return "bus:publish: " + e.getMessage();
        }
        return "Published " + eventType + " " + data + " (bus:stats counts it, bus:behaviours shows who consumes it)";
    }

    /** Counters per event type. */
    public String stats() {
        StringBuilder out = new StringBuilder(String.format("%-60s %12s %12s %8s %10s %10s %8s%n", "EVENT TYPE",
                "PUBLISHED", "DELIVERED", "FAILED", "UNHANDLED", "DISCARDED", "HELD"));
        for (EventTypeStatistics s : statistics.eventTypes()) {
            out.append(String.format("%-60s %12d %12d %8d %10d %10d %8d%n", s.eventType, s.published, s.delivered,
                    s.failed, s.unhandled, s.discarded, s.held));
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
