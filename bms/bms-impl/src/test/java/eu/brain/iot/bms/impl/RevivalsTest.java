package eu.brain.iot.bms.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.LongAdder;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import eu.brain.iot.bis.api.InstallException.Problem;
import eu.brain.iot.bis.api.InstalledBehaviour;
import eu.brain.iot.bms.api.BehaviourInstallFailed;
import eu.brain.iot.bms.api.BehaviourInstalled;
import eu.brain.iot.bms.monitoring.api.HistoryEntry;
import eu.brain.iot.eventing.spi.UnhandledEventPolicy.Disposition;

/**
 * A behaviour whose bundle stops or is uninstalled outside the installer is brought back without waiting for an event
 * ({@link Revivals}, through {@link BehaviourManager#wentAway}), with virtual time: the grace, what is left alone (a
 * bundle active again, one the installer did not install, the framework shutting down, an operator's stop), the
 * backoff and the give-up, a bundle that keeps going away, and the sharing of one request with held events.
 */
class RevivalsTest {

    private static final String DOOR_EVENT = "eu.brain.iot.warehouse.OpenDoor";
    private static final String DOOR = "eu.brain.iot.behaviours.door";
    private static final long BUNDLE = 42;
    /** retry 500 ms doubling to 4 s, deadline 10 s, rest 60 s, restart grace 1 s. */
    private static final Settings SETTINGS = new Settings(1_000, 60_000, 500, 4_000, 10_000, 0, 1_000, List.of(), 64,
            1_000);

    private final ManualScheduler clock = new ManualScheduler();
    private final FakeInstaller installer = new FakeInstaller();
    private final FakeHold bus = new FakeHold();
    private final RecordingBus alerts = new RecordingBus();
    private final RecordingLogger log = new RecordingLogger();
    private final ManagerCountersImpl counters = new ManagerCountersImpl();
    private final AtomicBoolean frameworkStopping = new AtomicBoolean();
    private final InstalledBehaviour door = new InstalledBehaviour();
    private BehaviourManager bms;

    @BeforeEach
    void start() {
        installer.offer(DOOR_EVENT, DOOR, "0.1.0");
        door.symbolicName = DOOR;
        door.version = "0.1.0";
        door.bundleId = BUNDLE;
        door.consumed = List.of(DOOR_EVENT);
        door.state = "RESOLVED"; // its bundle stopped
        installer.active.add(door);
        bms = new BehaviourManager(installer, bus, clock, new Alerts(alerts, Runnable::run, log.logger,
                new LongAdder()), log.logger, counters, SETTINGS, frameworkStopping::get);
        bms.start();
    }

    @Test
    void aStoppedBundleIsStartedAgainWhenTheGraceEndsWithoutAnyEvent() {
        stopped();
        clock.advance(999);
        assertThat(installer.requests).as("not during the grace").isEmpty();
        clock.advance(1);

        assertThat(installer.requests).singleElement().satisfies(r -> {
            assertThat(r.request().symbolicName).isEqualTo(DOOR);
            assertThat(r.request().versionRange).isEqualTo("[0.1.0,0.1.0]");
            assertThat(r.request().consumedTypes).containsExactly(DOOR_EVENT);
            assertThat(r.request().operator).isFalse();
            assertThat(r.request().reason).contains("its bundle was stopped outside the installer");
        });
        installer.last().succeed();
        door.state = "ACTIVE";
        clock.runDue();

        assertThat(bms.history()).singleElement().satisfies(e -> {
            assertThat(e.kind).isEqualTo("RESTARTED");
            assertThat(e.eventTypes).isEmpty();
            assertThat(e.behaviour).isEqualTo(DOOR + " 0.1.0");
            assertThat(e.durationMs).isEqualTo(1_000);
            assertThat(e.reason).contains("its bundle was stopped outside the installer");
        });
        assertThat(alerts.of(BehaviourInstalled.class)).singleElement()
                .satisfies(a -> assertThat(a.eventTypes).isEmpty());
        assertThat(counters.snapshot().installs).isEqualTo(1);
        assertThat(bus.unhandled + bus.handedOver).as("no event involved").isZero();
    }

    @Test
    void anUninstalledBundleIsInstalledAgain() {
        door.state = "UNINSTALLED";
        door.bundleId = -1;
        stopped();
        clock.advance(1_000);

        assertThat(installer.last().request().reason).contains("its bundle was uninstalled outside the installer");
        installer.last().succeed();
        clock.runDue();
        assertThat(bms.history()).extracting(e -> e.kind).containsExactly("REINSTALLED");
    }

    @Test
    void aBundleActiveAgainWithinTheGraceIsLeftAlone() {
        stopped(); // a refresh, an update: stopped, then started again
        clock.advance(500);
        door.state = "ACTIVE";
        clock.advance(10_000);
        assertThat(installer.requests).isEmpty();
        assertThat(bms.history()).isEmpty();
    }

    @Test
    void aBundleTheInstallerDoesNotListOrAnotherBundleOfTheSameNameIsLeftAlone() {
        bms.wentAway("org.apache.felix.gogo.shell", 7); // not the installer's
        installer.active.remove(door);
        stopped(); // the installer removed it (bis:uninstall): it is off its list first
        installer.active.add(door);
        bms.wentAway(DOOR, BUNDLE + 1); // an operator's own copy of the bundle
        clock.advance(10_000);
        assertThat(installer.requests).isEmpty();
    }

    @Test
    void nothingIsBroughtBackWhileTheFrameworkStops() {
        frameworkStopping.set(true);
        stopped();
        clock.advance(10_000);
        assertThat(installer.requests).as("stopping at the stop").isEmpty();

        frameworkStopping.set(false);
        stopped();
        clock.advance(500);
        frameworkStopping.set(true);
        clock.advance(10_000);
        assertThat(installer.requests).as("stopping when the grace ends").isEmpty();
    }

    @Test
    void anOperatorsStopIsRespectedWithoutRetryOrAlertAndALaterFaultIsActedOnAgain() {
        stopped();
        clock.advance(1_000);
        installer.last().fail(Problem.REMOVED_BY_OPERATOR, DOOR + " was removed or stopped by an operator (bis:stop)");
        clock.advance(60_000);

        assertThat(installer.requests).hasSize(1);
        assertThat(alerts.alerts).isEmpty();
        assertThat(bms.history()).isEmpty();
        assertThat(counters.snapshot().installFailures).isZero();
        assertThat(log.count("info", "Not bringing back")).isEqualTo(1);

        stopped(); // allowed, started, then stopped by a fault: acted on again at once (no rest)
        clock.advance(1_000);
        assertThat(installer.requests).hasSize(2);
    }

    @Test
    void aBundleThatFailsToStartAgainIsRetriedWithBackoffAlertedAndGivenUpOnAtTheDeadline() {
        stopped();
        clock.advance(1_000);
        long first = clock.now() - 1_000;
        installer.last().fail(Problem.START_FAILED, "its activator threw");
        stopped(); // the failed start stopped it again: part of this attempt
        clock.runDue();

        BehaviourInstallFailed alert = alerts.of(BehaviourInstallFailed.class).get(0);
        assertThat(alert.eventType).isNull();
        assertThat(alert.behaviour).isEqualTo(DOOR + " 0.1.0");
        assertThat(alert.problem).isEqualTo("START_FAILED");
        assertThat(alert.nextRetry).isEqualTo(clock.now() + 500);
        assertThat(alert.finalFailure).isFalse();
        List<Long> asked = new java.util.ArrayList<>(List.of(clock.now()));
        while (clock.now() < first + 20_000) {
            int before = installer.requests.size();
            clock.advance(100);
            if (installer.requests.size() > before) {
                asked.add(clock.now());
                installer.last().fail(Problem.START_FAILED, "its activator threw");
                stopped();
                clock.runDue();
            }
        }
        // attempts at 1 s, then 0.5, 1, 2, 4 s later; the next (4 s) would pass the deadline (10 s from the stop)
        assertThat(asked).containsExactly(first + 1_000, first + 1_500, first + 2_500, first + 4_500, first + 8_500);
        assertThat(alerts.of(BehaviourInstallFailed.class)).hasSize(5).last()
                .satisfies(a -> assertThat(a.finalFailure).isTrue());
        assertThat(bms.history()).extracting(e -> e.kind).containsExactly("INSTALL_FAILED", "INSTALL_FAILED",
                "INSTALL_FAILED", "INSTALL_FAILED", "GAVE_UP");
        assertThat(log.count("error", "Gave up bringing back")).isEqualTo(1);

        stopped(); // resting: its bundle going away is not acted on for negative.cache.ms
        clock.advance(30_000);
        assertThat(installer.requests).hasSize(5);
        clock.advance(60_000);
        stopped();
        clock.advance(1_000);
        assertThat(installer.requests).as("a new episode after the rest").hasSize(6);
    }

    @Test
    void aTamperedBundleIsGivenUpOnAtOnce() {
        door.state = "UNINSTALLED";
        stopped();
        clock.advance(1_000);
        installer.last().fail(Problem.HASH_MISMATCH, "SHA-256 differs");
        clock.advance(60_000);
        assertThat(installer.requests).hasSize(1);
        assertThat(bms.history()).extracting(e -> e.kind).containsExactly("GAVE_UP");
        assertThat(alerts.of(BehaviourInstallFailed.class)).singleElement()
                .satisfies(a -> assertThat(a.finalFailure).isTrue());
    }

    @Test
    void aBundleThatKeepsGoingAwayAfterComingBackIsNotALoop() {
        long first = clock.now();
        List<Long> asked = new java.util.ArrayList<>();
        stopped();
        while (awaitRequest(20_000)) {
            asked.add(clock.now() - first);
            installer.last().succeed();
            clock.runDue();
            clock.advance(100); // it lives 100 ms, then goes away again
            stopped();
        }
        // brought back 1 s after the first stop, then 1, 1, 2, 4 s after each next one (the backoff, at least the
        // grace); the next, 4 s after the stop at 9.5 s, would pass the deadline (10 s from the first stop)
        assertThat(asked).containsExactly(1_000L, 2_100L, 3_200L, 5_300L, 9_400L);
        HistoryEntry last = bms.history().get(bms.history().size() - 1);
        assertThat(last.kind).isEqualTo("GAVE_UP");
        assertThat(last.reason).contains("kept going away");
        assertThat(alerts.of(BehaviourInstallFailed.class)).singleElement()
                .satisfies(a -> assertThat(a.finalFailure).isTrue());
    }

    @Test
    void eventsHeldWhileItIsBroughtBackJoinItsRequestAndTheHistoryRecordsItOnce() {
        stopped();
        clock.advance(1_000);
        assertThat(bus.publish(bms, DOOR_EVENT)).isEqualTo(Disposition.HOLD);
        clock.runDue();
        assertThat(installer.requests).as("one request for both").hasSize(1);

        installer.last().succeed();
        bus.register(DOOR_EVENT);
        clock.runDue();
        assertThat(bus.handedOver).isEqualTo(1);
        assertThat(bms.history()).singleElement().satisfies(e -> {
            assertThat(e.kind).isEqualTo("RESTARTED");
            assertThat(e.eventTypes).containsExactly(DOOR_EVENT);
            assertThat(e.reason).contains("its bundle was stopped outside the installer");
        });
    }

    @Test
    void whenAnEventAskedForItFirstTheEventPathBringsItBackAlone() {
        stopped();
        assertThat(bus.publish(bms, DOOR_EVENT)).isEqualTo(Disposition.HOLD);
        clock.advance(1_000);
        assertThat(installer.requests).hasSize(1);
        assertThat(installer.last().request().reason).contains("had no consumer");
        installer.last().fail(Problem.START_FAILED, "its activator threw");
        clock.advance(SETTINGS.installDeadlineMs());
        assertThat(installer.requests).extracting(r -> r.request().reason)
                .allSatisfy(reason -> assertThat(reason).contains("had no consumer"));
        assertThat(bms.history()).isNotEmpty().extracting(e -> e.eventTypes)
                .allSatisfy(t -> assertThat(t).containsExactly(DOOR_EVENT));
    }

    @Test
    void aNegativeRestartGraceIsRefused() {
        assertThatThrownBy(() -> new Settings(1, 1, 1, 1, 1, 1, 1, List.of(), 1, -1))
                .hasMessageContaining("restart.grace.ms must be at least 0, was -1");
        assertThat(Settings.DEFAULTS.restartGraceMs()).isEqualTo(1_000);
    }

    /** Moves the clock on by 100 ms steps until a request is made; {@code false} when none came within the time. */
    private boolean awaitRequest(long withinMillis) {
        int before = installer.requests.size();
        for (long waited = 0; waited < withinMillis; waited += 100) {
            clock.advance(100);
            if (installer.requests.size() > before) {
                return true;
            }
        }
        return false;
    }

    /** The framework's bundle event for the door's bundle, as {@link BundleWatch} queues it. */
    private void stopped() {
        bms.wentAway(DOOR, BUNDLE);
    }
}
