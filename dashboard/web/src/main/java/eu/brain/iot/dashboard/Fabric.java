package eu.brain.iot.dashboard;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.api.InstalledBehaviour;
import eu.brain.iot.bms.monitoring.api.BehaviourManagerStatistics;
import eu.brain.iot.bms.monitoring.api.HistoryEntry;
import eu.brain.iot.eventing.monitoring.api.ConsumerStatistics;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;
import eu.brain.iot.eventing.monitoring.api.EventTypeStatistics;
import eu.brain.iot.edge.model.api.PollMonitor;
import eu.brain.iot.edge.model.api.PollStatistics;

/**
 * The fabric as the page shows it: the bus's per-type and per-consumer statistics, the behaviours the BIS
 * installed, the BMS's last decisions and the edge's polling counters. Each source is optional: a node without a
 * BMS shows no history. The services are asked on the dashboard's thread only; each answers from memory.
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

    /** A fresh reading of every source there is, as plain maps and lists. */
    Map<String, Object> read() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("eventTypes", bus == null ? List.of() : eventTypes(bus.eventTypes()));
        m.put("consumers", bus == null ? List.of() : consumers(bus.consumers()));
        m.put("behaviours", installer == null ? null : behaviours(installer.installed()));
        m.put("bmsHistory", bms == null ? null : history(bms.history()));
        m.put("polling", poll == null ? null : polling(poll.statistics()));
        return m;
    }

    private static List<Map<String, Object>> eventTypes(List<EventTypeStatistics> types) {
        List<Map<String, Object>> out = new ArrayList<>(types.size());
        for (EventTypeStatistics t : types) {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("eventType", t.eventType);
            m.put("published", t.published);
            m.put("delivered", t.delivered);
            m.put("failed", t.failed);
            m.put("unhandled", t.unhandled);
            m.put("held", t.held);
            out.add(m);
        }
        return out;
    }

    private static List<Map<String, Object>> consumers(List<ConsumerStatistics> consumers) {
        List<Map<String, Object>> out = new ArrayList<>(consumers.size());
        for (ConsumerStatistics c : consumers) {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("consumer", c.consumer);
            m.put("bundle", c.bundle);
            m.put("consumed", c.consumed);
            m.put("queueDepth", c.queueDepth);
            m.put("delivered", c.delivered);
            m.put("failures", c.failures);
            out.add(m);
        }
        return out;
    }

    private static List<Map<String, Object>> behaviours(List<InstalledBehaviour> installed) {
        List<Map<String, Object>> out = new ArrayList<>(installed.size());
        for (InstalledBehaviour b : installed) {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("symbolicName", b.symbolicName);
            m.put("version", b.version);
            m.put("state", b.state);
            m.put("installedAt", b.installedAt);
            m.put("reason", b.reason);
            m.put("consumed", b.consumed);
            out.add(m);
        }
        return out;
    }

    private static List<Map<String, Object>> history(List<HistoryEntry> history) {
        List<Map<String, Object>> out = new ArrayList<>();
        for (HistoryEntry h : history.subList(Math.max(0, history.size() - HISTORY), history.size())) {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("time", h.time);
            m.put("kind", h.kind);
            m.put("eventTypes", h.eventTypes);
            m.put("behaviour", h.behaviour);
            m.put("durationMs", h.durationMs);
            m.put("reason", h.reason);
            out.add(m);
        }
        return out;
    }

    private static Map<String, Object> polling(PollStatistics s) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("fleetUrl", s.fleetUrl);
        m.put("sent", s.sent);
        m.put("answered", s.answered);
        m.put("failed", s.failed);
        m.put("onTime", s.onTime);
        m.put("late", s.late);
        m.put("eventsWaiting", s.eventsWaiting);
        return m;
    }
}
