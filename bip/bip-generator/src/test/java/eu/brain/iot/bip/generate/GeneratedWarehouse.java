package eu.brain.iot.bip.generate;

import java.lang.reflect.Proxy;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Map;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;

/**
 * The generated behaviours of a system, compiled at run time and driven on a single-threaded, in-order bus: a
 * published event queues up and {@link #publish} hands every queued event, in order, to every behaviour. Extern
 * functions answer the default value of their result type and are recorded with the instance the behaviour named
 * ({@code bipInstance}) just before. Owned by the test thread.
 */
final class GeneratedWarehouse implements EventBus {

    /** An extern call: the group and component the behaviour announced, the function and its arguments. */
    record Call(String group, String component, String function, List<Object> args) {
    }

    final ClassLoader loader;
    private final Deque<BrainIoTEvent> queue = new ArrayDeque<>();
    private final List<BrainIoTEvent> published = new ArrayList<>();
    private final List<Object> behaviours = new ArrayList<>();
    final List<Call> calls = new ArrayList<>();
    private String group;
    private String component;

    GeneratedWarehouse(Toolchain tool, String root, Path out) {
        List<JavaFile> files = tool.generateInMemory(root);
        if (tool.diagnostics().hasErrors()) {
            throw new AssertionError("generation failed: " + tool.diagnostics().errors());
        }
        this.loader = InMemoryCompiler.compile(files, out);
    }

    /** Creates behaviour {@code javaClass} with externs {@code externsClass} (or none) and the configuration. */
    Object start(String javaClass, String externsClass, Map<String, Object> config) throws ReflectiveOperationException {
        Class<?> cls = loader.loadClass(javaClass);
        Object b;
        if (externsClass == null) {
            b = cls.getConstructor(EventBus.class, Map.class).newInstance(this, config);
        } else {
            Class<?> externs = loader.loadClass(externsClass);
            Object impl = Proxy.newProxyInstance(loader, new Class<?>[] {externs}, (proxy, method, args) -> {
                if (method.getName().equals("bipInstance")) {
                    group = (String) args[0];
                    component = (String) args[1];
                    return null;
                }
                calls.add(new Call(group, component, method.getName(), args == null ? List.of() : List.of(args)));
                Class<?> r = method.getReturnType();
                return r == int.class ? 1 : r == double.class ? 1.0 : r == boolean.class ? Boolean.FALSE : null;
            });
            b = cls.getConstructor(EventBus.class, externs, Map.class).newInstance(this, impl, config);
        }
        behaviours.add(b);
        drain();
        return b;
    }

    @Override
    public void deliver(BrainIoTEvent event) {
        published.add(event);
        queue.add(event);
    }

    @Override
    public void deliver(String eventType, Map<String, Object> eventData) {
        throw new UnsupportedOperationException("generated behaviours publish typed events");
    }

    @Override
    public boolean tryDeliver(BrainIoTEvent event) {
        deliver(event);
        return true;
    }

    @Override
    public boolean tryDeliver(String eventType, Map<String, Object> eventData) {
        throw new UnsupportedOperationException("generated behaviours publish typed events");
    }

    /** Publishes an event of the environment: type, group, then field names and values. */
    void publish(String type, String group, Object... fieldsAndValues) throws ReflectiveOperationException {
        BrainIoTEvent e = (BrainIoTEvent) loader.loadClass(type).getConstructor().newInstance();
        e.getClass().getField("group").set(e, group);
        for (int i = 0; i < fieldsAndValues.length; i += 2) {
            e.getClass().getField((String) fieldsAndValues[i]).set(e, fieldsAndValues[i + 1]);
        }
        deliver(e);
        drain();
    }

    @SuppressWarnings("unchecked")
    private void drain() {
        int guard = 0;
        while (!queue.isEmpty()) {
            if (++guard > 10_000) {
                throw new AssertionError("the behaviours keep publishing");
            }
            BrainIoTEvent e = queue.poll();
            for (Object b : behaviours) {
                ((SmartBehaviour<BrainIoTEvent>) b).notify(e);
            }
        }
    }

    /** @return the published events of a generated type (simple name in the events package) */
    List<Object> published(String type) throws ClassNotFoundException {
        Class<?> cls = loader.loadClass(type);
        return published.stream().filter(cls::isInstance).map(Object.class::cast).toList();
    }

    static Object field(Object event, String name) {
        try {
            return event.getClass().getField(name).get(event);
        } catch (ReflectiveOperationException e) {
            throw new AssertionError(e);
        }
    }

    static Object call(Object behaviour, String method, Object... args) {
        try {
            for (var m : behaviour.getClass().getMethods()) {
                if (m.getName().equals(method) && m.getParameterCount() == args.length) {
                    return m.invoke(behaviour, args);
                }
            }
            throw new AssertionError("no method " + method + "/" + args.length);
        } catch (ReflectiveOperationException e) {
            throw new AssertionError(e);
        }
    }
}
