package eu.brain.iot.eventing.integration;

import java.lang.reflect.Method;

import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;

/**
 * Calls the bus's Gogo commands as the shell does: the command service found by its {@code osgi.command.scope}, its
 * public method invoked reflectively (the command class is private to the bus bundle).
 */
final class BusShell {
    private final Object commands;

    BusShell(BundleContext context) throws Exception {
        ServiceReference<?>[] refs = context.getServiceReferences((String) null, "(osgi.command.scope=bus)");
        if (refs == null || refs.length != 1) {
            throw new IllegalStateException("expected one bus command service, found "
                    + (refs == null ? 0 : refs.length));
        }
        this.commands = context.getService(refs[0]);
    }

    String publish(String type, String... fields) throws Exception {
        Method m = commands.getClass().getMethod("publish", String.class, String[].class);
        return (String) m.invoke(commands, type, fields);
    }

    String behaviours() throws Exception {
        return (String) commands.getClass().getMethod("behaviours").invoke(commands);
    }
}
