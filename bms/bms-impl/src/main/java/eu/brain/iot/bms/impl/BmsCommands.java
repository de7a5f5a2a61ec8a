package eu.brain.iot.bms.impl;

import java.time.Instant;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;

import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;

import eu.brain.iot.bms.monitoring.api.BehaviourManagerStatistics;
import eu.brain.iot.bms.monitoring.api.HistoryEntry;
import eu.brain.iot.bms.monitoring.api.ManagerCounters;
import eu.brain.iot.bms.monitoring.api.PendingType;

/** Gogo commands {@code bms:pending}, {@code bms:history} and {@code bms:stats}. */
@Component(service = BmsCommands.class, property = { "osgi.command.scope=bms", "osgi.command.function=pending",
        "osgi.command.function=history", "osgi.command.function=stats" })
public final class BmsCommands {

    private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("HH:mm:ss.SSS")
            .withZone(ZoneId.systemDefault());

    private final BehaviourManagerStatistics statistics;

    @Activate
    public BmsCommands(@Reference BehaviourManagerStatistics statistics) {
        this.statistics = statistics;
    }

    /** The event types waiting for a behaviour (or not searched again for a while), their held events, since when. */
    public String pending() {
        StringBuilder out = new StringBuilder(String.format("%-56s %-20s %8s %10s %-12s %-12s %3s  %s%n",
                "EVENT TYPE", "STATE", "HELD", "UNHANDLED", "SINCE", "UNTIL", "TRY", "BEHAVIOUR / REASON"));
        for (PendingType p : statistics.pending()) {
            String detail = p.behaviour == null ? "" : p.behaviour;
            if (p.lastReason != null) {
                detail += (detail.isEmpty() ? "" : ": ") + p.lastReason;
            }
            out.append(String.format("%-56s %-20s %8d %10d %-12s %-12s %3d  %s%n", p.eventType, p.state,
                    p.heldEvents, p.unhandledEvents, time(p.since), p.until == 0 ? "-" : time(p.until), p.attempt,
                    detail));
        }
        return out.toString();
    }

    /** What the BMS did: installs, failures, types not found, events given up on, with times and durations. */
    public String history() {
        StringBuilder out = new StringBuilder(String.format("%-12s %-20s %-48s %-40s %9s %3s %6s  %s%n", "TIME",
                "WHAT", "EVENT TYPES", "BEHAVIOUR", "MS", "TRY", "HELD", "REASON"));
        for (HistoryEntry e : statistics.history()) {
            out.append(String.format("%-12s %-20s %-48s %-40s %9d %3d %6d  %s%n", time(e.time), e.kind,
                    String.join(",", e.eventTypes), e.behaviour == null ? "-" : e.behaviour, e.durationMs, e.attempt,
                    e.heldEvents, e.reason == null ? "" : e.reason));
        }
        return out.toString();
    }

    /** The BMS's counters. */
    public String stats() {
        ManagerCounters c = statistics.counters();
        return String.format("unhandled events %d, held %d, searches %d, installs %d, install failures %d, "
                + "types not found %d, held events given up on %d, alerts %d%n", c.unhandledEvents, c.heldEvents,
                c.searches, c.installs, c.installFailures, c.notFound, c.discardedEvents, c.alerts);
    }

    private static String time(long millis) {
        return TIME.format(Instant.ofEpochMilli(millis));
    }
}
