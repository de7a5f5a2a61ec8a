package eu.brain.iot.edge.impl;

/** The edge's polling counters, as a service private to this bundle (for its Gogo commands). */
interface EdgeMonitor {
    PollStats.Snapshot pollStats();

    String fleetUrl();
}
