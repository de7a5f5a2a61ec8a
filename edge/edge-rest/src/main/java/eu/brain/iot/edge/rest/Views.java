package eu.brain.iot.edge.rest;

import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceValue;

/**
 * The device model as JSON trees (maps and lists, in a stable order). Written out by hand rather than by Jackson's
 * bean mapping: the records hold {@link Instant}s (ISO-8601 text here, without the JSR-310 module) and the wire
 * format stays what this class says even when the records grow.
 */
final class Views {

    private Views() {
    }

    /** An entry of {@code GET /sensinact/providers}. */
    static Map<String, Object> summary(ProviderSnapshot p) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("id", p.id());
        m.put("kind", p.kind());
        m.put("status", p.status().name());
        m.put("lastPoll", time(p.lastPoll()));
        m.put("reason", p.reason());
        return m;
    }

    /** {@code GET /sensinact/providers/{p}}: the summary, every service's resources, and the actions. */
    static Map<String, Object> provider(ProviderSnapshot p) {
        Map<String, Object> m = summary(p);
        Map<String, Object> services = new LinkedHashMap<>();
        p.services().forEach((name, resources) -> services.put(name, resources(resources)));
        m.put("services", services);
        Map<String, Object> actions = new LinkedHashMap<>();
        p.actions().forEach((service, list) -> actions.put(service, List.copyOf(list)));
        m.put("actions", actions);
        return m;
    }

    /** {@code GET /sensinact/providers/{p}/services/{s}}. */
    static Map<String, Object> service(ProviderSnapshot p, String service) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("provider", p.id());
        m.put("service", service);
        m.put("resources", resources(p.services().getOrDefault(service, Map.of())));
        m.put("actions", p.actions().getOrDefault(service, List.of()));
        return m;
    }

    private static Map<String, Object> resources(Map<String, ResourceValue> resources) {
        Map<String, Object> m = new LinkedHashMap<>();
        resources.forEach((name, v) -> m.put(name, brief(v)));
        return m;
    }

    /** A resource inside its provider's view: value, timestamp, status. */
    static Map<String, Object> brief(ResourceValue v) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("value", v.value());
        m.put("timestamp", time(v.timestamp()));
        m.put("status", v.status().name());
        return m;
    }

    /** A resource on its own ({@code GET .../resources/{r}}, and each SSE event): where it is, then its value. */
    static Map<String, Object> resource(ResourceValue v) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("provider", v.provider());
        m.put("service", v.service());
        m.put("resource", v.resource());
        m.putAll(brief(v));
        return m;
    }

    /** The answer to an ACT: what was asked and what the device said. */
    static Map<String, Object> outcome(String provider, String service, String action, CommandOutcome o) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("provider", provider);
        m.put("service", service);
        m.put("action", action);
        m.put("accepted", o.accepted);
        m.put("command", o.command);
        m.put("commandId", o.commandId);
        m.put("missionId", o.missionId);
        m.put("deviceStatus", o.status);
        return m;
    }

    /** Action names without their parameter lists: {@code goTo(x,y)} is the action {@code goTo}. */
    static List<String> actionNames(List<String> actions) {
        List<String> names = new ArrayList<>();
        for (String a : actions) {
            int paren = a.indexOf('(');
            names.add(paren < 0 ? a : a.substring(0, paren));
        }
        return names;
    }

    static String time(Instant t) {
        return t == null ? null : t.toString();
    }
}
