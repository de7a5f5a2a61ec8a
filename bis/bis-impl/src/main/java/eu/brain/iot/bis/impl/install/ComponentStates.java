package eu.brain.iot.bis.impl.install;

import java.util.ArrayList;
import java.util.List;

import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.osgi.service.component.runtime.ServiceComponentRuntime;
import org.osgi.service.component.runtime.dto.ComponentConfigurationDTO;
import org.osgi.service.component.runtime.dto.ComponentDescriptionDTO;
import org.osgi.service.component.runtime.dto.UnsatisfiedReferenceDTO;

/**
 * What Declarative Services says of a bundle's components, in one line for the message of a behaviour whose smart
 * behaviours did not come: each component that is not active, and why (disabled; a reference or a configuration
 * missing; its activation failed, with the failure's first line). What {@code scr:info} shows, without the shell.
 * <p>
 * Stateless; any thread.
 */
final class ComponentStates {

    /** Characters kept of a failed activation's text (its first line). */
    static final int FAILURE_CHARS = 200;

    private ComponentStates() {
    }

    /** @return the components of the bundle that are not active, and why; or why that is not known */
    static String of(BundleContext context, Bundle bundle) {
        ServiceReference<ServiceComponentRuntime> ref = context.getServiceReference(ServiceComponentRuntime.class);
        ServiceComponentRuntime scr = ref == null ? null : context.getService(ref);
        if (scr == null) {
            return "Declarative Services is not running";
        }
        try {
            List<String> notActive = new ArrayList<>();
            int components = 0;
            for (ComponentDescriptionDTO d : scr.getComponentDescriptionDTOs(bundle)) {
                components++;
                String why = whyNotActive(scr, d);
                if (why != null) {
                    notActive.add(simpleName(d.name) + " " + why);
                }
            }
            if (components == 0) {
                return "the bundle has no components (bundle state " + Dtos.state(bundle) + ")";
            }
            return notActive.isEmpty() ? "its " + components + " components are active"
                    : "components not active: " + String.join("; ", notActive);
        } finally {
            context.ungetService(ref);
        }
    }

    private static String whyNotActive(ServiceComponentRuntime scr, ComponentDescriptionDTO d) {
        if (!scr.isComponentEnabled(d)) {
            return "disabled";
        }
        var configurations = scr.getComponentConfigurationDTOs(d);
        if (configurations.isEmpty()) {
            return "without configuration (" + d.configurationPolicy + ", PID " + String.join(", ",
                    d.configurationPid) + ")";
        }
        List<String> reasons = new ArrayList<>();
        for (ComponentConfigurationDTO c : configurations) {
            String why = switch (c.state) {
                case ComponentConfigurationDTO.ACTIVE, ComponentConfigurationDTO.SATISFIED -> null;
                case ComponentConfigurationDTO.UNSATISFIED_REFERENCE -> "missing " + references(c);
                case ComponentConfigurationDTO.UNSATISFIED_CONFIGURATION -> "missing its configuration (PID "
                        + String.join(", ", d.configurationPid) + ")";
                case ComponentConfigurationDTO.FAILED_ACTIVATION -> "failed to activate: " + firstLine(c.failure);
                default -> "in state " + c.state;
            };
            if (why != null) {
                reasons.add(why);
            }
        }
        return reasons.isEmpty() ? null : String.join(", ", reasons);
    }

    private static String references(ComponentConfigurationDTO c) {
        List<String> names = new ArrayList<>();
        for (UnsatisfiedReferenceDTO r : c.unsatisfiedReferences) {
            names.add(r.name + (r.target == null ? "" : " " + r.target));
        }
        return names.isEmpty() ? "a reference" : "reference " + String.join(", ", names);
    }

    static String firstLine(String text) {
        if (text == null || text.isBlank()) {
            return "(no reason given)";
        }
        String line = text.strip().lines().findFirst().orElse("");
        return line.length() > FAILURE_CHARS ? line.substring(0, FAILURE_CHARS) + "…" : line;
    }

    private static String simpleName(String name) {
        int dot = name.lastIndexOf('.');
        return dot < 0 ? name : name.substring(dot + 1);
    }
}
