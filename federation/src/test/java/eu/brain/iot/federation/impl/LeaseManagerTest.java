package eu.brain.iot.federation.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.lang.reflect.Proxy;
import java.time.Duration;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicBoolean;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.osgi.service.log.Logger;

import eu.brain.iot.edge.model.api.DeviceOwnership;
import eu.brain.iot.eventing.impl.BusCore;
import eu.brain.iot.federation.api.DeviceLease;

/**
 * Lease managers of two nodes on one bus (what the fabric does for leases is to carry them between the nodes' buses:
 * FabricTest), each over an edge of its own (a {@link DeviceOwnership} kept in memory): the shares are taken after
 * one lease period, a node that stops renewing loses its devices to the other, and when it comes back it gets its
 * share back, without any device owned by two live nodes at any time.
 */
class LeaseManagerTest {

    static final Duration DEADLINE = Duration.ofSeconds(30);
    static final long LEASE_MS = 400;
    static final long RENEW_MS = 50;
    static final Set<String> FLEET = Set.of("robot1", "robot2", "robot3", "robot4", "door1");

    /** Which live node owns each device now; a take of a device a live node owns is a violation. */
    final Map<String, String> holder = new ConcurrentHashMap<>();
    final List<String> violations = new CopyOnWriteArrayList<>();
    final BusCore bus = new BusCore(1024, 5_000, quiet());
    final List<LeaseManager> managers = new CopyOnWriteArrayList<>();

    @AfterEach
    void tearDown() {
        managers.forEach(LeaseManager::deactivate);
        bus.close();
    }

    /** An edge's ownership in memory, its share leased ({@code share.leased}): it owns nothing until it takes. */
    final class Edge implements DeviceOwnership {
        final String node;
        final Set<String> share;
        final Set<String> owned = Collections.synchronizedSet(new TreeSet<>());
        final AtomicBoolean alive = new AtomicBoolean(true);

        Edge(String node, Set<String> share) {
            this.node = node;
            this.share = share;
        }

        private void hold(String d) {
            String before = holder.putIfAbsent(d, node);
            if (before != null && !before.equals(node)) {
                violations.add(node + " took " + d + " while " + before + " held it");
            }
            owned.add(d);
        }

        /** Like kill -9: it holds nothing any more and never renews. */
        void die(LeaseManager m) {
            m.deactivate();
            alive.set(false);
            owned.forEach(d -> holder.remove(d, node));
            owned.clear();
        }

        @Override
        public String nodeName() {
            return node;
        }

        @Override
        public Set<String> owned() {
            return Set.copyOf(owned);
        }

        @Override
        public Set<String> share() {
            return share;
        }

        @Override
        public Set<String> fleet() {
            return FLEET;
        }

        @Override
        public boolean owns(String deviceId) {
            return owned.contains(deviceId);
        }

        @Override
        public synchronized Set<String> take(Set<String> ids) {
            Set<String> changed = new TreeSet<>(ids);
            changed.removeAll(owned);
            changed.forEach(this::hold);
            return changed;
        }

        @Override
        public synchronized Set<String> release(Set<String> ids) {
            Set<String> changed = new TreeSet<>(ids);
            changed.retainAll(owned);
            changed.forEach(d -> {
                owned.remove(d);
                holder.remove(d, node);
            });
            return changed;
        }
    }

    LeaseManager start(Edge edge) {
        LeaseManager m = new LeaseManager(bus, edge, edge.alive::get, LEASE_MS, RENEW_MS, LEASE_MS);
        bus.addTypedBehaviour(m, null, DeviceLease.class.getName());
        managers.add(m);
        return m;
    }

    @Test
    void aNodeThatStopsRenewingLosesItsDevicesAndGetsItsShareBackWhenItReturns() {
        Set<String> share1 = Set.of("robot1", "robot3", "door1");
        Set<String> share2 = Set.of("robot2", "robot4");
        Edge e1 = new Edge("node1", share1);
        start(e1);
        Edge e2 = new Edge("node2", share2);
        LeaseManager m2 = start(e2);
        await("each its share").atMost(DEADLINE).until(() -> e1.owned().equals(share1) && e2.owned().equals(share2));

        e2.die(m2);
        await("node1 takes node2's devices once its lease lapsed").atMost(DEADLINE)
                .until(() -> e1.owned().equals(FLEET));

        Edge back = new Edge("node2", share2); // started again
        start(back);
        await("node2's share back with node2").atMost(DEADLINE)
                .until(() -> e1.owned().equals(share1) && back.owned().equals(share2));
        assertThat(violations).as("no device held by two live nodes").isEmpty();
    }

    private static Logger quiet() {
        return (Logger) Proxy.newProxyInstance(Logger.class.getClassLoader(), new Class<?>[] { Logger.class },
                (proxy, method, args) -> method.getReturnType() == boolean.class ? false : null);
    }
}
