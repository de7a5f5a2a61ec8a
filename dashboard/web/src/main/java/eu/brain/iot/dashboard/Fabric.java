package eu.brain.iot.dashboard;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;

import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bms.monitoring.api.BehaviourManagerStatistics;
import eu.brain.iot.bms.monitoring.api.HistoryEntry;
import eu.brain.iot.edge.model.api.PollMonitor;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;
import eu.brain.iot.federation.monitoring.api.FabricMonitor;

/**
 * The fabric as the page shows it: the bus's per-type and per-consumer statistics, the behaviours the BIS
 * installed, the BMS's last decisions, the edge's polling counters and the fabric's nodes (this node and every other
 * node it knows), as the services' own DTOs (JSON writes their public fields). Each source is optional: a node
 * without a BMS shows no history, a node without a fabric configuration no nodes. The services are asked on the
 * dashboard's thread only; each answers from memory.
 */
final class Fabric {

    private static final int HISTORY = 20;

    private final EventBusStatistics bus;
    private final BundleInstaller installer;
    private final BehaviourManagerStatistics bms;
    private final PollMonitor poll;
    /** The fabric's monitor now, or {@code null}: it comes and goes with the node's fabric configuration. */
    private final Supplier<FabricMonitor> nodes;

    Fabric(EventBusStatistics bus, BundleInstaller installer, BehaviourManagerStatistics bms, PollMonitor poll,
            Supplier<FabricMonitor> nodes) {
        this.bus = bus;
        this.installer = installer;
        this.bms = bms;
        this.poll = poll;
        this.nodes = nodes;
    }

    /** A fresh reading of every source there is; a missing source is {@code null}. */
    Map<String, Object> read() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("eventTypes", bus == null ? null : bus.eventTypes());
        m.put("consumers", bus == null ? null : bus.consumers());
        m.put("behaviours", installer == null ? null : installer.installed());
        m.put("bmsHistory", bms == null ? null : last(bms.history()));
        m.put("polling", poll == null ? null : poll.statistics());
        FabricMonitor monitor = nodes.get();
        m.put("nodes", monitor == null ? null : monitor.status());
        return m;
    }

    private static List<HistoryEntry> last(List<HistoryEntry> history) {
        return history.subList(Math.max(0, history.size() - HISTORY), history.size());
    }
}
