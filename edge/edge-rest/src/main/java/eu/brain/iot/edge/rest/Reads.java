package eu.brain.iot.edge.rest;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceValue;

/**
 * The GET side of {@code /sensinact}: reads the device model and turns it into JSON trees. An unknown provider,
 * service or resource is a 404 that lists what does exist at that level.
 */
final class Reads {

    private final DeviceModel model;

    Reads(DeviceModel model) {
        this.model = model;
    }

    Object read(Route r) {
        return switch (r.kind()) {
            case INDEX -> index();
            case PROVIDERS -> model.providers().stream().map(Views::summary).toList();
            case PROVIDER -> Views.provider(provider(r.provider()));
            case SERVICES -> services(provider(r.provider()));
            case SERVICE -> Views.service(service(r), r.service());
            case RESOURCES -> resources(r);
            case RESOURCE -> Views.resource(resource(r));
            case ACT -> throw new IllegalStateException("ACT is not a read"); // Route.checkMethod keeps it out
        };
    }

    private Map<String, Object> index() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("providers", model.providers().stream().map(ProviderSnapshot::id).toList());
        m.put("paths", List.of(Route.SHAPES.split(", ")));
        return m;
    }

    ProviderSnapshot provider(String id) {
        return model.provider(id).orElseThrow(() -> HttpError.notFound("no provider '" + Echo.cut(id) + "'; providers: "
                + model.providers().stream().map(ProviderSnapshot::id).toList()));
    }

    /** Services with resources and services with actions only (a robot's {@code control}). */
    private static Set<String> serviceNames(ProviderSnapshot p) {
        Set<String> names = new TreeSet<>(p.services().keySet());
        names.addAll(p.actions().keySet());
        return names;
    }

    private static Map<String, Object> services(ProviderSnapshot p) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("provider", p.id());
        m.put("services", List.copyOf(serviceNames(p)));
        return m;
    }

    private ProviderSnapshot service(Route r) {
        ProviderSnapshot p = provider(r.provider());
        if (!serviceNames(p).contains(r.service())) {
            throw HttpError.notFound(p.id() + " has no service '" + Echo.cut(r.service()) + "'; services: " + serviceNames(p));
        }
        return p;
    }

    private Map<String, Object> resources(Route r) {
        ProviderSnapshot p = service(r);
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("provider", p.id());
        m.put("service", r.service());
        m.put("resources", List.copyOf(p.services().getOrDefault(r.service(), Map.of()).keySet()));
        m.put("actions", Views.actionNames(p.actions().getOrDefault(r.service(), List.of())));
        return m;
    }

    private ResourceValue resource(Route r) {
        ProviderSnapshot p = service(r);
        ResourceValue v = p.services().getOrDefault(r.service(), Map.of()).get(r.resource());
        if (v != null) {
            return v;
        }
        List<String> actions = p.actions().getOrDefault(r.service(), List.of());
        int i = Views.actionNames(actions).indexOf(r.resource());
        if (i >= 0) {
            throw HttpError.methodNotAllowed("GET", r.path(), "POST", r.resource() + " is an action, "
                    + actions.get(i) + ": POST its parameters as a JSON object to " + r.path() + "/act");
        }
        List<String> names = new ArrayList<>(p.services().getOrDefault(r.service(), Map.of()).keySet());
        names.addAll(Views.actionNames(actions));
        throw HttpError.notFound(p.id() + "/" + r.service() + " has no resource '" + Echo.cut(r.resource()) + "'; resources: "
                + names);
    }
}
