package eu.brain.iot.bms.impl;

import java.util.concurrent.atomic.LongAdder;

import eu.brain.iot.bms.monitoring.api.ManagerCounters;

/** The BMS's counters: incremented on any thread (publishers' and the BMS's), read by monitoring. */
final class ManagerCountersImpl {
    final LongAdder unhandled = new LongAdder();
    final LongAdder held = new LongAdder();
    final LongAdder searches = new LongAdder();
    final LongAdder installs = new LongAdder();
    final LongAdder installFailures = new LongAdder();
    final LongAdder notFound = new LongAdder();
    final LongAdder discarded = new LongAdder();
    final LongAdder alerts = new LongAdder();

    ManagerCounters snapshot() {
        ManagerCounters c = new ManagerCounters();
        c.unhandledEvents = unhandled.sum();
        c.heldEvents = held.sum();
        c.searches = searches.sum();
        c.installs = installs.sum();
        c.installFailures = installFailures.sum();
        c.notFound = notFound.sum();
        c.discardedEvents = discarded.sum();
        c.alerts = alerts.sum();
        return c;
    }
}
