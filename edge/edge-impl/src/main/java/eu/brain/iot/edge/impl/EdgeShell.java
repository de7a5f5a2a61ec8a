package eu.brain.iot.edge.impl;

import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;

import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.edge.model.api.PollMonitor;
import eu.brain.iot.edge.model.api.PollStatistics;
import eu.brain.iot.edge.model.api.ProviderSnapshot;

/** Gogo commands: {@code edge:robots}, {@code edge:doors}, {@code edge:provider ID}, {@code edge:stats}. */
@Component(service = EdgeShell.class, property = { "osgi.command.scope=edge", "osgi.command.function=robots",
        "osgi.command.function=doors", "osgi.command.function=provider", "osgi.command.function=stats" })
public final class EdgeShell {

    private final DeviceModel model;
    private final PollMonitor monitor;

    @Activate
    public EdgeShell(@Reference DeviceModel model, @Reference PollMonitor monitor) {
        this.model = model;
        this.monitor = monitor;
    }

    /** Every robot's live position and state. */
    public String robots() {
        StringBuilder out = new StringBuilder(String.format("%-12s %5s %5s %-7s %4s %-8s %-6s %-8s %-20s %s%n",
                "ROBOT", "X", "Y", "HEADING", "AREA", "STATE", "DETECT", "CART", "MISSION", "STATUS"));
        for (ProviderSnapshot p : model.providers()) {
            if (!"robot".equals(p.kind())) {
                continue;
            }
            Object missionType = p.value("mission", "type");
            String mission = missionType == null ? "-"
                    : missionType + " " + p.value("mission", "id") + " " + p.value("mission", "state");
            out.append(String.format("%-12s %5s %5s %-7s %4s %-8s %-6s %-8s %-20s %s%n", p.id(),
                    text(p, "position", "x"), text(p, "position", "y"), text(p, "position", "heading"),
                    text(p, "position", "area"), text(p, "state", "state"), text(p, "state", "detect"),
                    text(p, "cart", "cart"), mission, status(p)));
        }
        return out.toString();
    }

    /** Every door's state. */
    public String doors() {
        StringBuilder out = new StringBuilder(String.format("%-12s %5s %5s %-8s %s%n", "DOOR", "X", "Y", "STATE",
                "STATUS"));
        for (ProviderSnapshot p : model.providers()) {
            if ("door".equals(p.kind())) {
                out.append(String.format("%-12s %5s %5s %-8s %s%n", p.id(), text(p, "position", "x"),
                        text(p, "position", "y"), text(p, "door", "state"), status(p)));
            }
        }
        return out.toString();
    }

    /** One provider: every resource with its value, timestamp and status. */
    public String provider(String id) {
        ProviderSnapshot p = model.provider(id).orElse(null);
        if (p == null) {
            return "no provider '" + id + "'; try edge:robots or edge:doors";
        }
        StringBuilder out = new StringBuilder(p.kind() + " " + p.id() + ": " + status(p) + ", last answer "
                + p.lastPoll() + "\n");
        p.services().forEach((service, resources) -> resources.values().forEach(v -> out.append(String.format(
                "  %-10s %-12s %-24s %-11s %s%n", service, v.resource(), v.value(), v.status(), v.timestamp()))));
        p.actions().forEach((service, actions) -> out.append("  actions of ").append(service).append(": ")
                .append(actions).append('\n'));
        return out.toString();
    }

    /** Polling counters since the edge started. */
    public String stats() {
        PollStatistics s = monitor.statistics();
        long due = s.onTime + s.late + s.failed + s.skipped;
        return String.format("fleet %s%npolls sent %d, answered %d (%.1f/s), failed %d, skipped %d%n"
                + "on time %.2f%% (%d on time, %d late)%n"
                + "events waiting for the bus %d (refused %d times), robot positions coalesced %d%n",
                s.fleetUrl == null ? "(not configured yet)" : s.fleetUrl, s.sent, s.answered,
                s.seconds <= 0 ? 0.0 : s.answered / s.seconds, s.failed, s.skipped,
                due == 0 ? 100.0 : 100.0 * s.onTime / due, s.onTime, s.late, s.eventsWaiting, s.eventsRefused,
                s.positionsCoalesced);
    }

    private static String status(ProviderSnapshot p) {
        return p.reason() == null ? p.status().toString() : p.status() + " (" + p.reason() + ")";
    }

    private static String text(ProviderSnapshot p, String service, String resource) {
        Object v = p.value(service, resource);
        return v == null ? "-" : v.toString();
    }
}
