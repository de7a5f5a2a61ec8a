package eu.brain.iot.federation.impl;

import java.lang.reflect.Proxy;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;

import org.osgi.service.log.Logger;

import eu.brain.iot.eventing.impl.BusCore;
import eu.brain.iot.eventing.spi.EventForwarder;
import eu.brain.iot.eventing.spi.RemoteEvents;

/**
 * One fabric node for a multi-node test: the real bus core and a real {@link FabricNode} connected to a real
 * broker, in the test's JVM. Behaviours are registered with the bus; the node's interest follows them, as the
 * component's tracker does in a framework.
 */
final class TestNode implements Host, AutoCloseable {

    final String name;
    final BusCore bus;
    final Settings settings;
    FabricNode fabric;
    final List<String> log = new CopyOnWriteArrayList<>();
    private final Map<Long, InterestEntry> behaviours = new ConcurrentHashMap<>();
    private final Map<String, Integer> forwarders = new ConcurrentHashMap<>();
    /** By destination: forwarders removed since the node started. */
    private final Map<String, Integer> forwardersRemoved = new ConcurrentHashMap<>();
    /** The names of the threads that handed other nodes' events to the bus. */
    final Set<String> deliveringThreads = ConcurrentHashMap.newKeySet();
    private final RemoteEvents remoteEvents;

    /** A node not started yet: behaviours added now are there before the node joins. */
    TestNode(String name, Settings settings) throws Exception {
        this.name = name;
        this.settings = settings;
        this.bus = new BusCore(1024, 5_000, quietLogger());
        this.remoteEvents = new RemoteEvents() {
            @Override
            public boolean tryDeliverRemote(String type, List<String> types, Map<String, Object> data, Runnable done) {
                deliveringThreads.add(Thread.currentThread().getName());
                return bus.tryDeliverRemote(type, types, data, done);
            }

            @Override
            public boolean tryDeliverRemoteToBehaviours(String type, List<String> types, Map<String, Object> data,
                    Runnable done) {
                deliveringThreads.add(Thread.currentThread().getName());
                return bus.tryDeliverRemoteToBehaviours(type, types, data, done);
            }

            @Override
            public boolean tryDeliverGivenUp(String type, List<String> types, Map<String, Object> data,
                    long publishedMillis) {
                return bus.tryDeliverGivenUp(type, types, data, publishedMillis);
            }
        };
    }

    void start() throws Exception {
        fabric = new FabricNode(settings, this);
        fabric.localInterest(behaviours.values());
        fabric.start();
    }

    /** A typed behaviour that loads the event classes itself; the node announces it. */
    long addBehaviour(Object behaviour, String filter, String... consumed) {
        long id = bus.addTypedBehaviour(behaviour, filter, consumed);
        behaviours.put(id, new InterestEntry(List.of(consumed), filter));
        if (fabric != null) {
            fabric.localInterest(behaviours.values());
        }
        return id;
    }

    void removeBehaviour(long id) {
        bus.removeBehaviour(id);
        behaviours.remove(id);
        fabric.localInterest(behaviours.values());
    }

    NodeStats.Snapshot statsOf(String other) {
        return fabric.nodes().stream().filter(v -> v.node().equals(other)).findFirst().map(FabricNode.NodeView::stats)
                .orElse(new NodeStats().snapshot());
    }

    String statusOf(String other) {
        return fabric.nodes().stream().filter(v -> v.node().equals(other)).findFirst()
                .map(FabricNode.NodeView::status).orElse("unknown");
    }

    @Override
    public RemoteEvents remoteEvents() {
        return remoteEvents;
    }

    @Override
    public AutoCloseable addForwarder(String destination, InterestEntry entry, EventForwarder forwarder) {
        long id = bus.addForwarder(forwarder, destination, entry.filter(), entry.types().toArray(String[]::new));
        forwarders.merge(destination, 1, Integer::sum);
        return () -> {
            bus.removeBehaviour(id);
            forwarders.merge(destination, -1, Integer::sum);
            forwardersRemoved.merge(destination, 1, Integer::sum);
        };
    }

    /** @return the forwarders on this node's bus to {@code destination} now: what routes events there */
    int forwardersTo(String destination) {
        return forwarders.getOrDefault(destination, 0);
    }

    /** @return the forwarders to {@code destination} removed since this node started (a moment unrouted) */
    int forwardersRemovedTo(String destination) {
        return forwardersRemoved.getOrDefault(destination, 0);
    }

    @Override
    public void warn(String message, Object... args) {
        log.add("WARN " + format(message, args));
    }

    @Override
    public void info(String message, Object... args) {
        log.add("INFO " + format(message, args));
    }

    static String format(String message, Object... args) {
        StringBuilder b = new StringBuilder();
        int a = 0;
        for (int i = 0; i < message.length(); i++) {
            if (message.startsWith("{}", i) && a < args.length) {
                b.append(args[a++]);
                i++;
            } else {
                b.append(message.charAt(i));
            }
        }
        return b.toString();
    }

    /** Stop as a crash would: the fabric without a goodbye, and the bus with what it had queued. */
    void crash() {
        fabric.crash();
        bus.close();
    }

    @Override
    public void close() {
        fabric.close();
        bus.close();
    }

    static Collection<String> names(Collection<TestNode> nodes) {
        List<String> n = new ArrayList<>();
        nodes.forEach(t -> n.add(t.name));
        return n;
    }

    private static Logger quietLogger() {
        return (Logger) Proxy.newProxyInstance(Logger.class.getClassLoader(), new Class<?>[] { Logger.class },
                (proxy, method, args) -> method.getReturnType() == boolean.class ? Boolean.FALSE : null);
    }
}
