package eu.brain.iot.eventing.impl;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.EventBusOverflowException;
import eu.brain.iot.eventing.impl.TextTable.Column;
import eu.brain.iot.eventing.monitoring.api.ConsumerStatistics;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;
import eu.brain.iot.eventing.monitoring.api.EventTypeStatistics;

/**
 * Gogo commands {@code bus:stats}, {@code bus:behaviours} and {@code bus:publish}. Called on the shell's threads;
 * holds no state of its own.
 */
@Component(service = BusCommands.class, property = { "osgi.command.scope=bus", "osgi.command.function=stats",
        "osgi.command.function=behaviours", "osgi.command.function=publish" })
public final class BusCommands {

    static final String PUBLISH_USAGE = "usage: bus:publish TYPE key=value ... (values: 42, 1.5, true, "
            + "\"two words\"; nested: at.x=3), e.g. bus:publish eu.brain.iot.behaviours.events.ConnectorTypeDoor "
            + "(a robot's request to open the warehouse door: the door behaviour, installed on demand if missing, "
            + "opens the door; no robot is commanded)";

    /**
     * Widest behaviour and bundle names shown in full; longer ones are cut with an ellipsis. Event type names are
     * never cut (scripts read them from bus:stats): their column is as wide as the longest.
     */
    static final int MAX_BEHAVIOUR_WIDTH = 32;
    static final int MAX_BUNDLE_WIDTH = 32;
    static final String STALLED = "stalled";
    static final String RUNNING = "ok";

    private final EventBusStatistics statistics;
    private final EventBus bus;
    private final BundleContext context;

    @Activate
    public BusCommands(@Reference EventBusStatistics statistics, @Reference EventBus bus, BundleContext context) {
        this.statistics = statistics;
        this.bus = bus;
        this.context = context;
    }

    /**
     * Publish an event by hand: as an object of its class when a bundle of this node exports it (so that the
     * consumers of its supertypes take it too, as from any publisher), else untyped (typed behaviours that consume
     * the type receive it converted to their class). Errors come back as a message, not an exception: this is typed by a person. A type no bundle and no
     * behaviour knows is refused when known names are near it (a typo, another case), with those names.
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
        String note = "";
        if (!KnownEventTypes.consumed(statistics, eventType)) {
            Set<String> known = KnownEventTypes.all(context, statistics);
            if (!known.contains(eventType)) {
                List<String> near = NearestNames.nearest(eventType, known);
                if (!near.isEmpty()) {
                    return "bus:publish: no class named " + eventType + " is known on this node (no installed bundle "
                            + "has it, no behaviour consumes it); did you mean " + String.join(" or ", near)
                            + "? Nothing was published.";
                }
                note = " No class of that name is known on this node (no installed bundle has it, no behaviour "
                        + "consumes it): the Behaviour Management Service, if any, looks for a behaviour that consumes "
                        + "it in its repositories (bms:pending, bms:history).";
            }
        }
        Optional<Class<? extends BrainIoTEvent>> type = KnownEventTypes.eventClass(context, eventType);
        try {
            if (type.isPresent()) {
                bus.deliver(EventMaps.fromMap(data, type.get())); // typed: its supertypes' consumers take it too
            } else {
                bus.deliver(eventType, data);
            }
        } catch (EventBusOverflowException e) {
            return "bus:publish: " + e.getMessage();
        } catch (RuntimeException e) {
            return "bus:publish: the fields " + data + " do not make a " + eventType + " (" + e.getMessage()
                    + "); " + PUBLISH_USAGE;
        }
        return "Published " + eventType + " " + data + " (bus:stats counts it, bus:behaviours shows who consumes it)."
                + note;
    }

    /** Counters per event type. */
    public String stats() {
        TextTable table = new TextTable(Column.text("EVENT TYPE", Integer.MAX_VALUE), Column.number("PUBLISHED"),
                Column.number("DELIVERED"), Column.number("FAILED"), Column.number("UNHANDLED"),
                Column.number("DISCARDED"), Column.number("HELD"));
        for (EventTypeStatistics s : statistics.eventTypes()) {
            table.row(s.eventType, s.published, s.delivered, s.failed, s.unhandled, s.discarded, s.held);
        }
        return table + behaviours();
    }

    /** The registered smart behaviours with their queues; a stalled one (see the bus's overflow policy) says so. */
    public String behaviours() {
        TextTable table = new TextTable(Column.text("BEHAVIOUR", MAX_BEHAVIOUR_WIDTH),
                Column.text("BUNDLE", MAX_BUNDLE_WIDTH), Column.number("QUEUED"), Column.number("DELIVERED"),
                Column.number("FAILED"), Column.number("DISCARDED"), Column.text("STATE", STALLED.length()),
                Column.text("CONSUMES", Integer.MAX_VALUE));
        for (ConsumerStatistics c : statistics.consumers()) {
            String consumes = c.lastResort ? "(last resort: unhandled events)" : String.join(",", c.consumed);
            if (!c.filter.isEmpty()) {
                consumes += " where " + c.filter;
            }
            table.row(c.consumer, c.bundle, c.queueDepth, c.delivered, c.failures, c.discarded,
                    c.stalled ? STALLED : RUNNING, (c.untyped ? "[untyped] " : "") + consumes);
        }
        return table.toString();
    }
}
