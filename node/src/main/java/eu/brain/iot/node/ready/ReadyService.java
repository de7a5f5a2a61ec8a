package eu.brain.iot.node.ready;

import java.util.ArrayList;
import java.util.List;

/**
 * A service the ready line waits for, from the framework property {@value ReadyReporter#READY_SERVICES}: an interface
 * name, optionally {@code ;pid=<configuration PID>}: then it is waited for only when Config Admin holds that
 * configuration (the Bundle Installer runs only when configured, and a node started with another config folder may
 * have none: it must still say it is ready).
 *
 * @param name the service interface
 * @param pid the configuration PID it depends on, or {@code null}
 */
record ReadyService(String name, String pid) {

    /** Parses {@code a.B;pid=x, c.D}; blank entries are ignored. */
    static List<ReadyService> parse(String property) {
        List<ReadyService> services = new ArrayList<>();
        if (property == null) {
            return services;
        }
        for (String entry : property.split(",")) {
            String[] parts = entry.trim().split(";");
            if (parts[0].isBlank()) {
                continue;
            }
            String pid = null;
            for (int i = 1; i < parts.length; i++) {
                String attribute = parts[i].trim();
                if (attribute.startsWith("pid=")) {
                    pid = attribute.substring(4).trim();
                }
            }
            services.add(new ReadyService(parts[0].trim(), pid));
        }
        return List.copyOf(services);
    }
}
