package eu.brain.iot.eventing.impl;

import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.LongAdder;

import org.osgi.service.log.Logger;

import eu.brain.iot.eventing.monitoring.api.EventTypeStatistics;

/** Counters of one event type; updated by publishers and delivery threads at once, hence adders. */
final class EventTypeCounters {
    final String eventType;
    final LongAdder published = new LongAdder();
    final LongAdder delivered = new LongAdder();
    final LongAdder failed = new LongAdder();
    final LongAdder unhandled = new LongAdder();
    final LongAdder discarded = new LongAdder();
    /** Events of this type in the bus's hold now (a gauge: up when held, down when handed over or given up). */
    final LongAdder held = new LongAdder();
    /** Set once the first unhandled event of this type was logged, so that the log is not flooded. */
    final AtomicBoolean unhandledLogged = new AtomicBoolean();

    EventTypeCounters(String eventType) {
        this.eventType = eventType;
    }

    /** One event of this type published that nothing takes: counted, and logged the first time. */
    void countUnhandled(Logger log, String why) {
        published.increment();
        unhandled.increment();
        logUnhandled(log, why);
    }

    /** Logs, the first time only, that events of this type are counted as unhandled, and why. */
    void logUnhandled(Logger log, String why) {
        if (unhandledLogged.compareAndSet(false, true)) {
            log.warn("No smart behaviour consumes events of type {} and {}; such events are counted as "
                    + "'unhandled' (Gogo: bus:stats).", eventType, why);
        }
    }

    EventTypeStatistics snapshot() {
        EventTypeStatistics s = new EventTypeStatistics();
        s.eventType = eventType;
        s.published = published.sum();
        s.delivered = delivered.sum();
        s.failed = failed.sum();
        s.unhandled = unhandled.sum();
        s.discarded = discarded.sum();
        s.held = held.sum();
        return s;
    }
}
