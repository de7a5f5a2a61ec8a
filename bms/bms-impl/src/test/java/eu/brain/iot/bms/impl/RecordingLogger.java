package eu.brain.iot.bms.impl;

import java.lang.reflect.Proxy;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import org.osgi.service.log.Logger;

/** A {@link Logger} for unit tests that keeps "level: message format" of every info, warning and error. */
final class RecordingLogger {

    final List<String> entries = new CopyOnWriteArrayList<>();
    final Logger logger = (Logger) Proxy.newProxyInstance(Logger.class.getClassLoader(),
            new Class<?>[] { Logger.class }, (proxy, method, args) -> {
                String name = method.getName();
                if ((name.equals("info") || name.equals("warn") || name.equals("error")) && args != null
                        && args[0] instanceof String format) {
                    entries.add(name + ": " + format);
                }
                if (method.getReturnType() == boolean.class) {
                    return false;
                }
                return method.getReturnType() == String.class ? "test" : null;
            });

    long count(String level, String fragment) {
        return entries.stream().filter(e -> e.startsWith(level + ": ") && e.contains(fragment)).count();
    }
}
