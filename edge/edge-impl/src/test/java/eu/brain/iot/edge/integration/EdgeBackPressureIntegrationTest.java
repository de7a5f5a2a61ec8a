package eu.brain.iot.edge.integration;

import static eu.brain.iot.edge.integration.EdgeTestSupport.DEADLINE;
import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Hashtable;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.osgi.service.cm.ConfigurationAdmin;
import org.osgi.test.common.annotation.InjectBundleContext;
import org.osgi.test.common.annotation.InjectService;
import org.osgi.test.common.annotation.Property;
import org.osgi.test.common.annotation.Property.Scalar;
import org.osgi.test.common.annotation.config.WithConfiguration;

import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.RobotPositionChanged;
import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.edge.model.api.PollMonitor;
import eu.brain.iot.edge.model.api.PollStatistics;
import eu.brain.iot.eventing.annotation.SmartBehaviourNamespace;
import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;
import eu.brain.iot.robotsim.SimConfig;
import eu.brain.iot.robotsim.world.MapGenerator;

/**
 * A smart behaviour blocked on the edge's events does not hold up the polling of the fleet:
 * with the bus's queues made small (16 events), a behaviour that consumes every robot position and command outcome
 * blocks in its first {@code notify()} while the edge polls 1,000 robots every 500 ms. The bus refuses the edge's
 * events, which wait in the edge's outbox, while every poll goes on being sent and answered on time; commands sent
 * meanwhile are answered to their callers. Once the behaviour is released it receives every command outcome and
 * the newest position of every robot: nothing is dropped but positions replaced by newer ones.
 * <p>
 * Were the edge's fleet thread to wait for room on the bus, the first round of polls would park it for the bus's
 * overflow timeout per event, and the polls would stop.
 */
class EdgeBackPressureIntegrationTest {

    static final String BUS_PID = "eu.brain.iot.eventing";
    static final int ROBOTS = 1_000;
    static final int COMMANDS = 20;
    /** Polls in the measured window: 3 s of 1,000 robots at 2 Hz. */
    static final int WINDOW_POLLS = 6_000;

    @InjectBundleContext
    BundleContext context;
    @InjectService(timeout = 5_000)
    ConfigurationAdmin configurationAdmin;
    @InjectService(timeout = 5_000)
    DeviceModel model;
    @InjectService(timeout = 5_000)
    PollMonitor monitor;

    /** Blocks in its first call until released; then keeps what it receives. */
    static final class BlockedBehaviour implements SmartBehaviour<BrainIoTEvent> {
        final CountDownLatch entered = new CountDownLatch(1);
        final CountDownLatch release = new CountDownLatch(1);
        final Map<String, RobotPositionChanged> lastPosition = new ConcurrentHashMap<>();
        final Set<String> outcomes = ConcurrentHashMap.newKeySet();

        @Override
        public void notify(BrainIoTEvent event) {
            entered.countDown();
            try {
                release.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            if (event instanceof RobotPositionChanged p) {
                lastPosition.put(p.robotId, p);
            } else if (event instanceof CommandOutcome o) {
                outcomes.add(o.commandId);
            }
        }
    }

    /** The bus's configuration of this test is deleted after it (osgi-test): wait for the bus's defaults again. */
    @AfterAll
    static void busDefaultsAgain(@InjectBundleContext BundleContext context) {
        awaitBusProperty(context, "queue.capacity", 65_536);
    }

    @Test
    @WithConfiguration(pid = BUS_PID, location = "?", properties = {
        @Property(key = "queue.capacity", value = "16", scalar = Scalar.Integer),
        // longer than the test: the blocked behaviour is slow to the bus, not stalled (a stalled one stops taking
        // events, eventbus/README.md), so the edge's events wait for it
        @Property(key = "overflow.timeout.ms", value = "600000", scalar = Scalar.Long) })
    void aBlockedBehaviourDoesNotHoldUpThePollingOf1000Robots() throws Exception {
        BlockedBehaviour blocked = new BlockedBehaviour();
        EdgeTestSupport edge = null;
        try {
            awaitBusProperty(context, "queue.capacity", 16);
            Hashtable<String, Object> properties = new Hashtable<>();
            properties.put(SmartBehaviourNamespace.CONSUMED_PROPERTY,
                    new String[] { RobotPositionChanged.class.getName(), CommandOutcome.class.getName() });
            // unregistered by osgi-test's CloseableBundleContext after the test
            context.registerService(SmartBehaviour.class.getName(), blocked, properties);

            SimConfig fleet = SimConfig.builder().map(MapGenerator.generate(200, 100, ROBOTS, 20, 1, 7))
                    .manualStep(true).build();
            edge = EdgeTestSupport.start(context, configurationAdmin, model, fleet,
                    Map.of("poll.period.ms", 500L, "request.timeout.ms", 2_000L));
            assertThat(blocked.entered.await(DEADLINE.toMillis(), TimeUnit.MILLISECONDS)).isTrue();
            await("the bus refuses the edge's events").atMost(DEADLINE)
                    .until(() -> monitor.statistics().eventsWaiting > 0);

            // a fresh framework: let the JIT warm up on five rounds of polls before the measured window
            long warm = monitor.statistics().answered + 5 * ROBOTS * 2L;
            await("five rounds of polls").atMost(DEADLINE).pollInterval(Duration.ofMillis(50))
                    .until(() -> monitor.statistics().answered >= warm);
            PollStatistics before = monitor.statistics();
            List<CompletableFuture<CommandOutcome>> commands = new ArrayList<>();
            List<String> robots = edge.sim.robotIds();
            for (int i = 0; i < COMMANDS; i++) {
                commands.add(model.act(robots.get(i), "control", "cancel", Map.of()).toCompletableFuture());
            }
            CompletableFuture.allOf(commands.toArray(CompletableFuture[]::new)).get(DEADLINE.toMillis(),
                    TimeUnit.MILLISECONDS);
            await("another " + WINDOW_POLLS + " polls answered").atMost(DEADLINE).pollInterval(Duration.ofMillis(50))
                    .until(() -> monitor.statistics().answered >= before.answered + WINDOW_POLLS);
            PollStatistics after = monitor.statistics();

            long onTime = after.onTime - before.onTime;
            long late = after.late - before.late;
            // Skipped: a device's previous poll still open at its next period. One stall of this JVM (a collection,
            // another module's tests on the same two cores) holds every poll open once: 1,000 skipped, seen once in
            // CI. A fleet thread waiting for the bus would hold every poll for the overflow timeout: all but a few.
            assertThat(after.skipped - before.skipped).as("polls skipped: a device's previous poll still open")
                    .isLessThanOrEqualTo(WINDOW_POLLS / 4);
            assertThat(after.failed - before.failed).as("polls failed").isZero();
            // On time: sent within 500 ms +- 50 ms of the device's previous poll. A fleet thread that waited for the
            // bus would stall every poll for the bus's overflow timeout (5 s): nearly every poll late, by seconds.
            // What a loaded machine does to a JVM running the simulator, the edge and the test is different: some
            // polls late by a few hundred ms (seen: 482 late of 10,000, p99 266 ms, at load 15 on 2 cores; another
            // run's p99 reached the histogram's 1 s top). So the test asserts what blocking would break, with room for
            // scheduling: at least half the polls on time. The speed target itself is the polling benchmark's
            // (BENCHMARKS.md, "Edge polling": 100% on time on a quiet machine).
            assertThat(onTime).as("polls on time (%d late, |interval - period| p99 %.1f ms) while the behaviour "
                    + "was blocked", late, after.deviationP99Millis)
                    .isGreaterThanOrEqualTo((long) Math.ceil(0.5 * (onTime + late)));
            assertThat(after.eventsWaiting).as("the behaviour was still blocked: events still waiting").isPositive();
            assertThat(after.eventsRefused).isGreaterThan(before.eventsRefused);

            blocked.release.countDown();
            List<String> sent = commands.stream().map(c -> c.join().commandId).toList();
            await("every command outcome and every robot's position delivered").atMost(DEADLINE).untilAsserted(() -> {
                assertThat(blocked.outcomes).containsAll(sent);
                assertThat(blocked.lastPosition.keySet()).containsAll(robots);
                assertThat(monitor.statistics().eventsWaiting).isZero();
            });
        } finally {
            blocked.release.countDown();
            if (edge != null) {
                edge.close();
            }
        }
    }

    private static void awaitBusProperty(BundleContext context, String key, Object value) {
        await("the bus configured with " + key + "=" + value).atMost(DEADLINE).untilAsserted(() -> {
            ServiceReference<EventBus> ref = context.getServiceReference(EventBus.class);
            assertThat(ref).isNotNull();
            assertThat(ref.getProperty(key)).isEqualTo(value);
        });
    }
}
