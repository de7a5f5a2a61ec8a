package eu.brain.iot.bms.integration;

import static org.assertj.core.api.Assertions.assertThat;
import static java.nio.charset.StandardCharsets.UTF_8;
import static org.awaitility.Awaitility.await;

import java.net.URLDecoder;
import java.nio.file.Files;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleEvent;
import org.osgi.framework.SynchronousBundleListener;

import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bms.api.BehaviourInstallFailed;
import eu.brain.iot.bms.api.BehaviourInstalled;
import eu.brain.iot.bms.integration.tb.Order;
import eu.brain.iot.bms.integration.tb.OrderBehaviourActivator;
import eu.brain.iot.bms.integration.tb.Refill;
import eu.brain.iot.bms.monitoring.api.BehaviourManagerStatistics;
import eu.brain.iot.bms.monitoring.api.HistoryEntry;

/**
 * A behaviour the BMS had installed, whose bundle is stopped or uninstalled outside the installer, comes back without
 * waiting for an event (scenario/README, "Known limits": the robot behaviour stopped while every robot queued at a
 * door only it opens; no robot moved, so no event came). In Felix, with the real bus, BMS and BIS: not one event of
 * the behaviour's types is published after its bundle went away, yet it is active again with its smart behaviour
 * registered with the bus, recorded by the BMS ({@code RESTARTED}, {@code REINSTALLED}) and the installer (journal,
 * {@code bis:list}) as when an event brings it back. An operator's {@code bis:stop}, and the installer's own
 * uninstall, are left as they are. {@code restart.grace.ms} is the default (1 s).
 */
class BroughtBackIntegrationTest extends BmsTestBase {

    /** Longer than the grace and the installer's answer: what is left alone is still so after it. */
    static final Duration LEFT_ALONE = Duration.ofSeconds(4);

    private final List<String> orderBundleEvents = new CopyOnWriteArrayList<>();

    @AfterEach
    void letItStart() {
        System.clearProperty(OrderBehaviourActivator.FAIL_START);
    }

    @Test
    void aBehaviourWhoseBundleIsStoppedIsStartedAgainWithoutAnyEvent() throws Exception {
        configure();
        Bundle first = installedByAnEvent();
        long[] published = publishedOrdersAndRefills();

        first.stop(); // as a failing behaviour's bundle would be, or Gogo's stop <id>

        awaitActiveOnTheBus(first);
        assertThat(orderBundleEvents).as("it did stop, then was started again").containsSubsequence("STOPPED",
                "STARTED");
        assertThat(bundles(ORDERS)).as("the same bundle, not installed twice").singleElement()
                .satisfies(b -> assertThat(b.getBundleId()).isEqualTo(first.getBundleId()));
        assertThat(publishedOrdersAndRefills()).as("no event of its types was published").isEqualTo(published);
        HistoryEntry restarted = awaitHistory("RESTARTED");
        assertThat(restarted.eventTypes).isEmpty();
        assertThat(restarted.behaviour).isEqualTo(ORDERS + " 1.0.0");
        assertThat(restarted.reason).contains("its bundle was stopped outside the installer");
        assertThat(command("bms", "history")).contains("RESTARTED").contains("stopped outside the installer");
        assertThat(bisCommand("list")).contains("restarted: ").contains("its bundle was RESOLVED")
                .contains("its bundle was stopped outside the installer");
        assertThat(Files.readString(temp.resolve("journal").resolve("history.log")))
                .containsPattern("\\trestarted\\t" + ORDERS + "\\t");
        await().atMost(DEADLINE).until(() -> alertsOf(BehaviourInstalled.class).size() == 2);
        assertThat(alertsOf(BehaviourInstalled.class).get(1).eventTypes).isEmpty();

        bus.deliver(order("p", 1));
        await().atMost(DEADLINE).until(() -> acks.size() == 2);
    }

    @Test
    void aBehaviourWhoseBundleIsUninstalledIsInstalledAgainWithoutAnyEvent() throws Exception {
        BundleInstaller installer = configure();
        Bundle first = installedByAnEvent();
        long[] published = publishedOrdersAndRefills();

        first.uninstall(); // as Gogo's uninstall <id> would, not bis:uninstall

        await().atMost(DEADLINE).until(() -> bundle(ORDERS) != null);
        Bundle again = bundle(ORDERS);
        assertThat(again.getBundleId()).isNotEqualTo(first.getBundleId());
        awaitActiveOnTheBus(again);
        assertThat(publishedOrdersAndRefills()).as("no event of its types was published").isEqualTo(published);
        HistoryEntry reinstalled = awaitHistory("REINSTALLED");
        assertThat(reinstalled.reason).contains("its bundle was uninstalled outside the installer");
        assertThat(installer.installed()).singleElement().satisfies(b -> {
            assertThat(b.state).isEqualTo("ACTIVE");
            assertThat(b.bundleId).isEqualTo(again.getBundleId());
        });
        // history.log encodes each reason as a URL component
        assertThat(URLDecoder.decode(Files.readString(temp.resolve("journal").resolve("history.log")), UTF_8))
                .containsPattern("\\tvanished\\t" + ORDERS + "\\t").contains("uninstalled outside the installer");
    }

    /**
     * {@code bis:stop} is the operator's: the BMS sees the bundle stop and leaves it stopped (no restart, no alert).
     * Once the operator starts it again ({@code bis:install}), a stop outside the installer is a fault again.
     */
    @Test
    void aBehaviourAnOperatorStoppedWithBisStopStaysStoppedAndAFaultAfterBisInstallIsActedOnAgain() throws Exception {
        configure();
        Bundle first = installedByAnEvent();

        assertThat(bisCommand("stop", ORDERS)).startsWith("stopped " + ORDERS);

        await().during(LEFT_ALONE).atMost(DEADLINE).until(() -> first.getState() == Bundle.RESOLVED);
        assertThat(historyKinds()).containsExactly("INSTALLED");
        assertThat(alertsOf(BehaviourInstallFailed.class)).isEmpty();
        assertThat(bisCommand("list")).contains("removed or stopped by an operator: " + ORDERS);

        assertThat(bisCommand("install", ORDERS)).startsWith("installed " + ORDERS);
        assertThat(first.getState()).isEqualTo(Bundle.ACTIVE);
        first.stop();
        awaitActiveOnTheBus(first);
        awaitHistory("RESTARTED");
    }

    @Test
    void theInstallersOwnUninstallIsNotUndone() throws Exception {
        BundleInstaller installer = configure();
        installedByAnEvent();

        installer.uninstall(ORDERS, "no longer needed", false).getValue();

        await().during(LEFT_ALONE).atMost(DEADLINE).until(() -> bundle(ORDERS) == null);
        assertThat(installer.installed()).isEmpty();
        assertThat(historyKinds()).containsExactly("INSTALLED");
    }

    /** A restart that fails is retried with backoff, each failure alerted; it comes back once it can start. */
    @Test
    void aBundleThatFailsToStartAgainIsRetriedWithAnAlertUntilItStarts() throws Exception {
        configure();
        configureBms("retry.initial.ms", 2_000L); // time for the test to see the first failure before the retry
        Bundle first = installedByAnEvent();
        System.setProperty(OrderBehaviourActivator.FAIL_START, "true");

        first.stop();

        await().atMost(DEADLINE).until(() -> !alertsOf(BehaviourInstallFailed.class).isEmpty());
        BehaviourInstallFailed failed = alertsOf(BehaviourInstallFailed.class).get(0);
        assertThat(failed.eventType).as("no event asked for it").isNull();
        assertThat(failed.behaviour).isEqualTo(ORDERS + " 1.0.0");
        assertThat(failed.problem).isEqualTo("START_FAILED");
        assertThat(failed.finalFailure).isFalse();
        assertThat(failed.nextRetry).isPositive();
        assertThat(first.getState()).isEqualTo(Bundle.RESOLVED);

        System.clearProperty(OrderBehaviourActivator.FAIL_START);
        awaitActiveOnTheBus(first);
        HistoryEntry restarted = awaitHistory("RESTARTED");
        assertThat(restarted.attempt).isGreaterThanOrEqualTo(2);
        assertThat(historyKinds()).startsWith("INSTALLED", "INSTALL_FAILED").endsWith("RESTARTED");
    }

    /** Installs the behaviour as the BMS does for its first event, and watches its bundle's events. */
    private Bundle installedByAnEvent() {
        bus.deliver(order("p", 0));
        await().atMost(DEADLINE).until(() -> acks.size() == 1);
        await().atMost(DEADLINE).until(() -> historyKinds().contains("INSTALLED"));
        Bundle bundle = bundle(ORDERS);
        // through the test's CloseableBundleContext: removed when the test ends
        context.addBundleListener((SynchronousBundleListener) e -> {
            if (e.getBundle().getBundleId() == bundle.getBundleId()) {
                orderBundleEvents.add(e.getType() == BundleEvent.STOPPED ? "STOPPED"
                        : e.getType() == BundleEvent.STARTED ? "STARTED" : String.valueOf(e.getType()));
            }
        });
        return bundle;
    }

    private void awaitActiveOnTheBus(Bundle bundle) {
        await().atMost(DEADLINE).until(() -> bundle.getState() == Bundle.ACTIVE && busStatistics.consumers().stream()
                .anyMatch(c -> ORDERS.equals(c.bundle)));
    }

    private HistoryEntry awaitHistory(String kind) {
        await().atMost(DEADLINE).until(() -> historyKinds().contains(kind));
        return history().stream().filter(e -> e.kind.equals(kind)).reduce((a, b) -> b).orElseThrow();
    }

    private List<HistoryEntry> history() {
        return service(BehaviourManagerStatistics.class).history();
    }

    private List<String> historyKinds() {
        return history().stream().map(e -> e.kind).toList();
    }

    private long[] publishedOrdersAndRefills() {
        return new long[] { typeStatistics(Order.class.getName()).published,
                typeStatistics(Refill.class.getName()).published };
    }
}
