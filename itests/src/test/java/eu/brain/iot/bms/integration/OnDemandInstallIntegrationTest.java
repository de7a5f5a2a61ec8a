package eu.brain.iot.bms.integration;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.nio.file.Files;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicReference;

import org.junit.jupiter.api.Test;
import org.osgi.framework.Bundle;

import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bms.api.BehaviourInstallFailed;
import eu.brain.iot.bms.api.BehaviourInstalled;
import eu.brain.iot.bms.api.BehaviourNotFound;
import eu.brain.iot.bms.integration.tb.Order;
import eu.brain.iot.bms.integration.tb.Refill;
import eu.brain.iot.bms.monitoring.api.BehaviourManagerStatistics;
import eu.brain.iot.eventing.monitoring.api.EventTypeStatistics;

/**
 * Behaviours installed on demand, in Felix, with the real bus, Behaviour Management Service and Bundle Installer
 * (the Felix resolver), from a real index of a real behaviour bundle: what reaches the behaviour's {@code notify()}
 * (it answers each event with an acknowledgement), what the framework holds, and the BMS's alerts.
 */
class OnDemandInstallIntegrationTest extends BmsTestBase {

    @Test
    void anUnhandledEventInstallsTheBehaviourThatConsumesItFromTheIndexAndReachesIt() throws Exception {
        BundleInstaller installer = configure();
        assertThat(bundle(ORDERS)).isNull();

        bus.deliver(order("p", 0));

        await().atMost(DEADLINE).until(() -> acks.size() == 1);
        assertThat(acks.get(0)).containsEntry("type", Order.class.getName()).containsEntry("seq", 0)
                .containsEntry("ownClass", true);
        // the installer journals a behaviour once its bundles started, so the behaviour may take its first event
        // a moment before installed() lists it
        await().atMost(DEADLINE).until(() -> !installer.installed().isEmpty());
        assertThat(installer.installed()).singleElement().satisfies(b -> {
            assertThat(b.symbolicName).isEqualTo(ORDERS);
            assertThat(b.reason).contains(Order.class.getName());
        });
        await().atMost(DEADLINE).until(() -> !alertsOf(BehaviourInstalled.class).isEmpty());
        assertThat(alertsOf(BehaviourInstalled.class).get(0).behaviour).isEqualTo(ORDERS);
        assertThat(service(BehaviourManagerStatistics.class).history()).extracting(e -> e.kind)
                .containsExactly("INSTALLED");
    }

    @Test
    void aBurstFromFourPublishersWhileTheInstallRunsReachesTheBehaviourOnceEachInPublishOrder() throws Exception {
        configure();
        int publishers = 4;
        int perPublisher = 2_500;
        CountDownLatch go = new CountDownLatch(1);
        AtomicReference<Throwable> failure = new AtomicReference<>();
        List<Thread> threads = new ArrayList<>();
        for (int p = 0; p < publishers; p++) {
            String name = "publisher-" + p;
            Thread t = new Thread(() -> {
                try {
                    go.await();
                    for (int i = 0; i < perPublisher; i++) {
                        bus.deliver(order(name, i));
                    }
                } catch (Throwable e) {
                    failure.set(e);
                }
            }, name);
            t.start();
            threads.add(t);
        }
        go.countDown();
        for (Thread t : threads) {
            t.join();
        }
        assertThat(failure.get()).isNull();

        await().atMost(DEADLINE).until(() -> acks.size() >= publishers * perPublisher);
        Map<Object, List<Integer>> byPublisher = new HashMap<>();
        for (Map<String, Object> ack : acks) {
            byPublisher.computeIfAbsent(ack.get("publisher"), k -> new ArrayList<>()).add((Integer) ack.get("seq"));
        }
        assertThat(byPublisher).hasSize(publishers);
        byPublisher.forEach((publisher, seqs) -> {
            assertThat(seqs).as("%s: every event once", publisher).hasSize(perPublisher);
            for (int i = 0; i < perPublisher; i++) {
                assertThat(seqs.get(i)).as("%s's event %d in order", publisher, i).isEqualTo(i);
            }
        });
        EventTypeStatistics orders = typeStatistics(Order.class.getName());
        assertThat(orders.unhandled).isZero();
        assertThat(orders.held).isZero();
        assertThat(service(BehaviourManagerStatistics.class).counters().heldEvents)
                .as("events held during the install").isPositive();
        assertThat(bundles(ORDERS)).hasSize(1);
    }

    @Test
    void aBundleWhoseBytesDoNotMatchItsIndexIsNeverInstalledAndFailsAtOnceWithAnAlertThatSaysWhy() throws Exception {
        repository.tamper();
        configure();
        Set<Long> before = bundleIds();
        long unhandledBefore = typeStatistics(Order.class.getName()).unhandled; // the bus counts since its start

        bus.deliver(order("p", 0));

        await().atMost(DEADLINE).until(() -> !alertsOf(BehaviourInstallFailed.class).isEmpty());
        BehaviourInstallFailed alert = alertsOf(BehaviourInstallFailed.class).get(0);
        assertThat(alert.problem).isEqualTo("HASH_MISMATCH");
        assertThat(alert.eventType).isEqualTo(Order.class.getName());
        assertThat(alert.reason).contains("SHA-256");
        assertThat(alert.finalFailure).as("a tampered bundle does not fix itself: no retry").isTrue();
        assertThat(alert.nextRetry).isZero();
        assertThat(bundleIds()).isEqualTo(before);
        assertThat(bundle(ORDERS)).isNull();
        assertThat(acks).isEmpty();
        assertThat(service(BehaviourManagerStatistics.class).history()).extracting(e -> e.kind)
                .containsExactly("GAVE_UP");
        assertThat(service(BehaviourManagerStatistics.class).counters().installFailures).isEqualTo(1);
        await().atMost(DEADLINE).until(() -> typeStatistics(Order.class.getName()).unhandled == unhandledBefore + 1);
        assertThat(typeStatistics(Order.class.getName()).held).isZero();
    }

    @Test
    void twoEventTypesThatNeedTheSameBundleAtOnceCauseOneInstall() throws Exception {
        configure();
        CountDownLatch go = new CountDownLatch(1);
        Thread refills = new Thread(() -> {
            try {
                go.await();
                bus.deliver(refill("r", 0));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        refills.start();
        go.countDown();
        bus.deliver(order("o", 0));
        refills.join();

        await().atMost(DEADLINE).until(() -> acks.size() == 2);
        assertThat(acks).extracting(a -> a.get("type")).containsExactlyInAnyOrder(Order.class.getName(),
                Refill.class.getName());
        assertThat(bundles(ORDERS)).hasSize(1);
        // the BMS tells of the install once the installer returned: the behaviour may have taken its events first
        await().atMost(DEADLINE).until(() -> !alertsOf(BehaviourInstalled.class).isEmpty());
        assertThat(alertsOf(BehaviourInstalled.class)).hasSize(1);
    }

    @Test
    void aBehaviourStoppedByAFailureComesBackWithTheNextEventButNotOneAnOperatorRemoved() throws Exception {
        BundleInstaller installer = configure();
        configureBms("restart.grace.ms", 600_000L); // the event brings it back, not the BMS's watch of its bundle
        bus.deliver(order("p", 0));
        await().atMost(DEADLINE).until(() -> acks.size() == 1);

        bundle(ORDERS).stop(); // as a failing behaviour's bundle would be
        await().atMost(DEADLINE)
                .until(() -> busStatistics.consumers().stream().noneMatch(c -> ORDERS.equals(c.bundle)));
        bus.deliver(order("p", 1));
        await().atMost(DEADLINE).until(() -> acks.size() == 2);
        assertThat(acks.get(1)).containsEntry("seq", 1);
        assertThat(bundle(ORDERS).getState()).isEqualTo(Bundle.ACTIVE);

        installer.uninstall(ORDERS, "bis:uninstall by an operator", true).getValue();
        assertThat(bundle(ORDERS)).isNull();
        int alertsBefore = alerts.size();
        bus.deliver(order("p", 2));
        await().atMost(DEADLINE).until(() -> alerts.size() > alertsBefore);
        assertThat(alerts.subList(alertsBefore, alerts.size())).allSatisfy(a -> assertThat(a)
                .isInstanceOfAny(BehaviourInstallFailed.class, BehaviourNotFound.class));
        bus.deliver(order("p", 3));
        await().atMost(DEADLINE).until(() -> typeStatistics(Order.class.getName()).unhandled >= 2);
        assertThat(bundle(ORDERS)).isNull();
        assertThat(acks).hasSize(2);
    }

    /**
     * A fault during the scenario: a behaviour bundle stopped mid-scenario (as Gogo's {@code stop <id>}
     * does) is started again by the BIS when the BMS holds its next events; one uninstalled behind the installer's back
     * ({@code Bundle.uninstall()}, not {@code bis:uninstall}) is installed again. Every event arrives once, in order.
     * The BMS's watch of behaviour bundles, which would bring it back without an event, waits longer than the test
     * ({@code restart.grace.ms}): {@link BroughtBackIntegrationTest} tests it.
     */
    @Test
    void aBehaviourStoppedOrUninstalledMidScenarioComesBackAndEveryEventArrivesOnceInOrder() throws Exception {
        BundleInstaller installer = configure();
        configureBms("restart.grace.ms", 600_000L);
        long unhandledBefore = typeStatistics(Order.class.getName()).unhandled; // the bus counts since its start
        publishOrders(0, 5);
        await().atMost(DEADLINE).until(() -> acks.size() == 5);
        Bundle first = bundle(ORDERS);

        first.stop();
        awaitNoConsumerOf(ORDERS);
        publishOrders(5, 505);
        await().atMost(DEADLINE).until(() -> acks.size() == 505);
        assertThat(bundles(ORDERS)).as("started again, not installed twice").singleElement()
                .satisfies(b -> assertThat(b.getBundleId()).isEqualTo(first.getBundleId()))
                .satisfies(b -> assertThat(b.getState()).isEqualTo(Bundle.ACTIVE));
        assertThat(bisCommand("list")).contains("restarted: ").contains("its bundle was RESOLVED")
                .contains("an event of type " + Order.class.getName() + " had no consumer");

        first.uninstall();
        awaitNoConsumerOf(ORDERS);
        publishOrders(505, 1_005);
        await().atMost(DEADLINE).until(() -> acks.size() == 1_005);
        assertThat(bundles(ORDERS)).as("installed again").singleElement()
                .satisfies(b -> assertThat(b.getBundleId()).isNotEqualTo(first.getBundleId()))
                .satisfies(b -> assertThat(b.getState()).isEqualTo(Bundle.ACTIVE));

        assertThat(acks).extracting(a -> a.get("seq")).as("every event once, in publish order")
                .containsExactlyElementsOf(java.util.stream.IntStream.range(0, 1_005).boxed().toList());
        EventTypeStatistics orders = typeStatistics(Order.class.getName());
        assertThat(orders.unhandled).as("none given up").isEqualTo(unhandledBefore);
        assertThat(orders.held).isZero();
        assertThat(service(BehaviourManagerStatistics.class).history()).extracting(e -> e.kind)
                .containsExactly("INSTALLED", "RESTARTED", "REINSTALLED");
        assertThat(installer.installed()).singleElement().satisfies(b -> assertThat(b.state).isEqualTo("ACTIVE"));
        String history = Files.readString(temp.resolve("journal").resolve("history.log"));
        assertThat(history).containsPattern("\\trestarted\\t" + ORDERS + "\\t")
                .containsPattern("\\tvanished\\t" + ORDERS + "\\t");
    }

    /** An operator's bis:stop is not undone by the BMS; bis:install starts the behaviour again at once. */
    @Test
    void aBehaviourAnOperatorStoppedWithBisStopStaysStoppedUntilTheOperatorBringsItBack() throws Exception {
        configure();
        bus.deliver(order("p", 0));
        await().atMost(DEADLINE).until(() -> acks.size() == 1);
        long id = bundle(ORDERS).getBundleId();
        long unhandledBefore = typeStatistics(Order.class.getName()).unhandled; // the bus counts since its start

        assertThat(bisCommand("stop", ORDERS)).startsWith("stopped " + ORDERS).contains("bis:allow " + ORDERS);
        assertThat(bundle(ORDERS).getState()).isEqualTo(Bundle.RESOLVED);
        bus.deliver(order("p", 1));
        await().atMost(DEADLINE).until(() -> !alertsOf(BehaviourInstallFailed.class).isEmpty());
        assertThat(alertsOf(BehaviourInstallFailed.class).get(0).problem).isEqualTo("REMOVED_BY_OPERATOR");
        assertThat(alertsOf(BehaviourInstallFailed.class).get(0).reason).contains("bis:stop by an operator");
        // given up, counted as unhandled: at once, or by the BMS's sweep when the bus held it after the refusal came
        await().atMost(DEADLINE).until(() -> typeStatistics(Order.class.getName()).unhandled == unhandledBefore + 1);
        assertThat(typeStatistics(Order.class.getName()).held).isZero();
        assertThat(bundle(ORDERS).getState()).isEqualTo(Bundle.RESOLVED);
        assertThat(bisCommand("list")).contains("removed or stopped by an operator: " + ORDERS);

        assertThat(bisCommand("install", ORDERS)).startsWith("installed " + ORDERS);
        assertThat(bundle(ORDERS).getBundleId()).isEqualTo(id);
        assertThat(bundle(ORDERS).getState()).isEqualTo(Bundle.ACTIVE);
        bus.deliver(order("p", 2));
        await().atMost(DEADLINE).until(() -> acks.size() == 2);
        assertThat(acks).extracting(a -> a.get("seq")).as("the event published while it was stopped was given up")
                .containsExactly(0, 2);
        assertThat(bisCommand("list")).doesNotContain("stopped by an operator: ")
                .contains("started again (its bundle was RESOLVED): bis:install " + ORDERS + " by an operator");
    }

    @Test
    void anEventTypeNoRepositoryHasGivesOneAlertAndItsPublisherNeverWaits() throws Exception {
        configure();
        String nobody = "eu.brain.iot.bms.integration.NoOneConsumesThis";
        for (int i = 0; i < 100_000; i++) {
            bus.deliver(nobody, Map.of("seq", i));
        }
        await().atMost(DEADLINE).until(() -> !alertsOf(BehaviourNotFound.class).isEmpty());
        assertThat(alertsOf(BehaviourNotFound.class)).singleElement().satisfies(a -> {
            assertThat(a.eventType).isEqualTo(nobody);
            assertThat(a.heldEvents).isZero();
        });
        EventTypeStatistics stats = typeStatistics(nobody);
        assertThat(stats.unhandled).isEqualTo(100_000);
        assertThat(stats.held).isZero();
        assertThat(service(BehaviourManagerStatistics.class).counters().heldEvents)
                .as("not one of them was held: the publisher never waited for an install").isZero();
        assertThat(service(BehaviourManagerStatistics.class).counters().searches).isEqualTo(1);
    }
}
