package eu.brain.iot.dashboard;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bms.monitoring.api.BehaviourManagerStatistics;
import eu.brain.iot.bms.monitoring.api.HistoryEntry;
import eu.brain.iot.edge.model.api.PollMonitor;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;

/**
 * The fabric as the page shows it: the bus's per-type and per-consumer statistics, the behaviours the BIS
 * installed, the BMS's last decisions and the edge's polling counters, as the services' own DTOs (JSON writes their
 * public fields). Each source is optional: a node without a BMS shows no history. The services are asked on the
 * dashboard's thread only; each answers from memory.
 */
final class Fabric {

    private static final int HISTORY = 20;

    private final EventBusStatistics bus;
    private final BundleInstaller installer;
    private final BehaviourManagerStatistics bms;
    private final PollMonitor poll;

    Fabric(EventBusStatistics bus, BundleInstaller installer, BehaviourManagerStatistics bms, PollMonitor poll) {
        this.bus = bus;
        this.installer = installer;
        this.bms = bms;
        this.poll = poll;
    }

    /** A fresh reading of every source there is; a missing source is {@code null}. */
    Map<String, Object> read() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("eventTypes", bus == null ? null : bus.eventTypes());
        m.put("consumers", bus == null ? null : bus.consumers());
        m.put("behaviours", installer == null ? null : installer.installed());
        m.put("bmsHistory", bms == null ? null : last(bms.history()));
        m.put("polling", poll == null ? null : poll.statistics());
        return m;
    }

    private static List<HistoryEntry> last(List<HistoryEntry> history) {
        return history.subList(Math.max(0, history.size() - HISTORY), history.size());
    }
}
