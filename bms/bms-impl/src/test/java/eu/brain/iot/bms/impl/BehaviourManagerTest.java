package eu.brain.iot.bms.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.LongAdder;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import eu.brain.iot.bis.api.InstallException.Problem;
import eu.brain.iot.bis.api.InstalledBehaviour;
import eu.brain.iot.bms.api.BehaviourInstallFailed;
import eu.brain.iot.bms.api.BehaviourInstalled;
import eu.brain.iot.bms.api.BehaviourNotFound;
import eu.brain.iot.bms.monitoring.api.HistoryEntry;
import eu.brain.iot.bms.monitoring.api.PendingType;
import eu.brain.iot.eventing.spi.UnhandledEventPolicy.Disposition;

/**
 * The BMS core's decisions, with virtual time ({@link ManualScheduler}): what it answers the bus, what it asks the
 * installer, retries and backoff, the deadline, the negative cache, operator removals, alerts and history.
 */
class BehaviourManagerTest {

    private static final String DOOR_EVENT = "eu.brain.iot.warehouse.OpenDoor";
    private static final String DOOR = "eu.brain.iot.behaviours.door";
    private static final String ROBOT_EVENT = "eu.brain.iot.warehouse.Position";
    private static final String NOBODY = "eu.brain.iot.edge.api.BatteryLevel";

    private final ManualScheduler clock = new ManualScheduler();
    private final FakeInstaller installer = new FakeInstaller();
    private final FakeHold bus = new FakeHold();
    private final RecordingBus alerts = new RecordingBus();
    private final RecordingLogger log = new RecordingLogger();
    private final ManagerCountersImpl counters = new ManagerCountersImpl();
    private BehaviourManager bms;

    private static final Settings SETTINGS = new Settings(1_000, 60_000, 500, 4_000, 10_000, 1_000, 1_000,
            List.of("eu.brain.iot.ignored.*"), 16, 1_000);

    @BeforeEach
    void start() {
        installer.offer(DOOR_EVENT, DOOR, "0.1.0");
        bms = new BehaviourManager(installer, bus, clock, new Alerts(alerts, Runnable::run, log.logger,
                new LongAdder()), log.logger, counters, SETTINGS, () -> false);
        bms.start();
    }

    @Test
    void theFirstEventOfATypeWithACandidateIsHeldAndOneInstallIsRequested() {
        assertThat(bus.publish(bms, DOOR_EVENT, "eu.brain.iot.warehouse.Command")).isEqualTo(Disposition.HOLD);
        clock.runDue();
        for (int i = 0; i < 99; i++) {
            assertThat(bus.publish(bms, DOOR_EVENT, "eu.brain.iot.warehouse.Command")).isEqualTo(Disposition.HOLD);
        }
        clock.runDue();

        assertThat(installer.finds).hasValue(1);
        assertThat(installer.requests).hasSize(1);
        var request = installer.last().request();
        assertThat(request.symbolicName).isEqualTo(DOOR);
        assertThat(request.versionRange).isEqualTo("[0.1.0,0.1.0]");
        assertThat(request.consumedTypes).containsExactly(DOOR_EVENT, "eu.brain.iot.warehouse.Command");
        assertThat(request.operator).isFalse();
        assertThat(request.reason).contains(DOOR_EVENT);
        assertThat(bms.states().get(DOOR_EVENT)).isInstanceOf(TypeState.Installing.class);

        installer.last().succeed();
        bus.register(DOOR_EVENT); // the bus hands the 100 held events over as the behaviour registers
        clock.runDue();

        assertThat(bus.handedOver).isEqualTo(100);
        assertThat(bus.discards).isEmpty();
        BehaviourInstalled installed = alerts.of(BehaviourInstalled.class).get(0);
        assertThat(installed.behaviour).isEqualTo(DOOR);
        assertThat(installed.eventTypes).containsExactly(DOOR_EVENT);
        assertThat(bms.history()).extracting(e -> e.kind).containsExactly("INSTALLED");
        assertThat(counters.snapshot().installs).isEqualTo(1);
        assertThat(counters.snapshot().heldEvents).isEqualTo(100);
    }

    @Test
    void aTypeNoRepositoryHasIsUnhandledAtOnceAlertedOnceAndNotSearchedAgainUntilTheCacheExpires() {
        assertThat(bus.publish(bms, NOBODY)).isEqualTo(Disposition.LAST_RESORT);
        for (int i = 0; i < 100_000; i++) {
            bus.publish(bms, NOBODY);
        }
        clock.runDue();

        assertThat(installer.finds).hasValue(1);
        assertThat(installer.requests).isEmpty();
        assertThat(bus.unhandled).isEqualTo(100_001);
        assertThat(bus.count(NOBODY)).isZero(); // never held: the publisher never waits
        List<BehaviourNotFound> notFound = alerts.of(BehaviourNotFound.class);
        assertThat(notFound).hasSize(1);
        assertThat(notFound.get(0).eventType).isEqualTo(NOBODY);
        assertThat(notFound.get(0).heldEvents).isZero();
        assertThat(notFound.get(0).retryAfter).isEqualTo(clock.now() + 60_000);
        assertThat(log.count("warn", "No repository offers")).isEqualTo(1);
        PendingType pending = pendingOf(NOBODY);
        assertThat(pending.state).isEqualTo("NOT_FOUND");
        assertThat(pending.unhandledEvents).isEqualTo(100_001);

        clock.advance(60_000); // the negative cache expires: the next event searches again
        assertThat(bus.publish(bms, NOBODY)).isEqualTo(Disposition.LAST_RESORT);
        clock.runDue();
        assertThat(installer.finds).hasValue(2);
        assertThat(alerts.of(BehaviourNotFound.class)).hasSize(2);
        assertThat(log.count("warn", "No repository offers")).isEqualTo(1); // logged once per type
    }

    @Test
    void theBmsNeverSearchesForItsOwnAlerts() {
        assertThat(bms.unhandled(BehaviourNotFound.class.getName(), List.of(BehaviourNotFound.class.getName(),
                "eu.brain.iot.eventing.api.BrainIoTEvent"), Map::of)).isEqualTo(Disposition.LAST_RESORT);
        assertThat(bms.unhandled("x.MyAlert", List.of("x.MyAlert", BehaviourInstallFailed.class.getName()), Map::of))
                .isEqualTo(Disposition.LAST_RESORT);
        assertThat(bms.unhandled("eu.brain.iot.ignored.Tick", List.of("eu.brain.iot.ignored.Tick"), Map::of))
                .isEqualTo(Disposition.LAST_RESORT);
        assertThat(installer.finds).hasValue(0);
    }

    @Test
    void aFailedInstallIsAlertedAndRetriedWithDoublingBackoffWhileItsEventsStayHeld() {
        bus.publish(bms, DOOR_EVENT);
        clock.runDue();
        installer.last().fail(Problem.DOWNLOAD_FAILED, "http://127.0.0.1:1/door.jar: connection refused");
        clock.runDue();

        BehaviourInstallFailed alert = alerts.of(BehaviourInstallFailed.class).get(0);
        assertThat(alert.problem).isEqualTo("DOWNLOAD_FAILED");
        assertThat(alert.reason).contains("connection refused");
        assertThat(alert.attempt).isEqualTo(1);
        assertThat(alert.nextRetry).isEqualTo(clock.now() + 500);
        assertThat(alert.finalFailure).isFalse();
        assertThat(bus.publish(bms, DOOR_EVENT)).isEqualTo(Disposition.HOLD); // still held while waiting
        assertThat(pendingOf(DOOR_EVENT).state).isEqualTo("RETRY_WAIT");

        clock.advance(499);
        assertThat(installer.requests).hasSize(1);
        clock.advance(1);
        assertThat(installer.requests).hasSize(2); // after 500 ms
        installer.last().fail(Problem.START_FAILED, "door.jar: bundle activator threw an exception");
        clock.runDue();
        clock.advance(999);
        assertThat(installer.requests).hasSize(2);
        clock.advance(1);
        assertThat(installer.requests).hasSize(3); // after 1000 ms: doubled
        assertThat(alerts.of(BehaviourInstallFailed.class).get(1).attempt).isEqualTo(2);

        installer.last().succeed();
        bus.register(DOOR_EVENT);
        clock.runDue();
        assertThat(bus.handedOver).isEqualTo(2);
        assertThat(bus.discards).isEmpty();
        assertThat(alerts.of(BehaviourInstalled.class).get(0).attempt).isEqualTo(3);
        assertThat(bms.history()).extracting(e -> e.kind).containsExactly("INSTALL_FAILED", "INSTALL_FAILED",
                "INSTALLED");
    }

    @Test
    void aBundleThatDoesNotMatchItsIndexFailsAtOnceWithTheReasonAndIsNotRetried() {
        bus.publish(bms, DOOR_EVENT);
        bus.publish(bms, DOOR_EVENT);
        clock.runDue();
        installer.last().fail(Problem.HASH_MISMATCH, "door.jar: SHA-256 abc differs from the index's def");
        clock.runDue();

        BehaviourInstallFailed alert = alerts.of(BehaviourInstallFailed.class).get(0);
        assertThat(alert.problem).isEqualTo("HASH_MISMATCH");
        assertThat(alert.reason).contains("SHA-256 abc differs");
        assertThat(alert.finalFailure).isTrue();
        assertThat(alert.nextRetry).isZero();
        assertThat(alert.heldEvents).isEqualTo(2);
        assertThat(bus.discards).singleElement().asString().contains("does not match its index")
                .contains("nor tried again");
        assertThat(bus.publish(bms, DOOR_EVENT)).isEqualTo(Disposition.LAST_RESORT);
        assertThat(bms.history()).extracting(e -> e.kind).containsExactly("GAVE_UP");
        assertThat(log.count("error", "Gave up installing")).isEqualTo(1);
        clock.advance(30_000);
        assertThat(installer.requests).as("no retry").hasSize(1);
        assertThat(alerts.of(BehaviourInstallFailed.class)).hasSize(1);
    }

    @Test
    void anInstallThatNeverAnswersIsGivenUpNamingWhatTheInstallerIsDoing() {
        installer.activities = List.of("downloading " + DOOR + " 0.1.0 from http://127.0.0.1:9/door.jar: 12 of 4000"
                + " bytes after 9 s", "downloading other.Behaviour 1.0.0 from http://127.0.0.1:9/other.jar: 0 bytes"
                        + " after 1 s");
        bus.publish(bms, DOOR_EVENT);
        clock.runDue();
        assertThat(installer.requests).hasSize(1); // and it never answers

        clock.advance(SETTINGS.installDeadlineMs() + SETTINGS.retryMaxMs());

        assertThat(bus.discards).singleElement().asString().contains("no answer from the installer")
                .contains("downloading " + DOOR + " 0.1.0 from http://127.0.0.1:9/door.jar: 12 of 4000 bytes")
                .doesNotContain("other.Behaviour");
        assertThat(alerts.of(BehaviourInstallFailed.class)).singleElement().extracting(a -> a.reason).asString()
                .contains("no answer from the installer; it is downloading " + DOOR + " 0.1.0 from"
                        + " http://127.0.0.1:9/door.jar");
    }

    @Test
    void pastTheDeadlineHeldEventsAreDiscardedWithTheReasonAndTheTypeRests() {
        bus.publish(bms, DOOR_EVENT);
        bus.publish(bms, DOOR_EVENT);
        clock.runDue();
        int failures = 0;
        while (bms.states().get(DOOR_EVENT) instanceof TypeState.Installing) {
            installer.last().fail(Problem.UNRESOLVED, "missing package eu.brain.iot.x");
            failures++;
            clock.runDue();
            clock.advance(SETTINGS.retryMaxMs());
        }
        assertThat(failures).isBetween(3, 6); // 500 + 1000 + 2000 + 4000 ms < 10 s deadline
        assertThat(bus.discards).singleElement().asString().contains(DOOR_EVENT).contains("kept failing")
                .contains("missing package");
        BehaviourInstallFailed last = alerts.of(BehaviourInstallFailed.class).get(failures - 1);
        assertThat(last.finalFailure).isTrue();
        assertThat(last.heldEvents).isEqualTo(2);
        assertThat(counters.snapshot().discardedEvents).isEqualTo(2);
        assertThat(bus.publish(bms, DOOR_EVENT)).isEqualTo(Disposition.LAST_RESORT);
        assertThat(log.count("error", "Gave up installing")).isEqualTo(1);
        int requests = installer.requests.size();
        clock.advance(30_000);
        assertThat(installer.requests).hasSize(requests); // no more retries
    }

    @Test
    void aBehaviourRemovedByAnOperatorIsNotRetriedAndItsEventsAreCountedUnhandled() {
        bus.publish(bms, DOOR_EVENT);
        clock.runDue();
        installer.last().fail(Problem.REMOVED_BY_OPERATOR, "an operator removed " + DOOR + " (bis:uninstall)");
        clock.runDue();
        clock.advance(30_000);

        assertThat(installer.requests).hasSize(1);
        assertThat(bus.publish(bms, DOOR_EVENT)).isEqualTo(Disposition.LAST_RESORT);
        assertThat(bus.discards).singleElement().asString().contains("operator");
        assertThat(alerts.of(BehaviourInstallFailed.class).get(0).finalFailure).isTrue();
        assertThat(pendingOf(DOOR_EVENT).state).isEqualTo("REMOVED_BY_OPERATOR");
    }

    @Test
    void twoTypesThatNeedTheSameBehaviourAtOnceShareOneInstall() {
        installer.offer(ROBOT_EVENT, DOOR, "0.1.0");
        bus.publish(bms, DOOR_EVENT);
        bus.publish(bms, ROBOT_EVENT);
        clock.runDue();
        assertThat(installer.requests).hasSize(1);
        installer.last().succeed();
        clock.runDue();
        assertThat(bms.states().values()).allMatch(s -> s instanceof TypeState.Installed);
        assertThat(alerts.of(BehaviourInstalled.class).get(0).eventTypes).containsExactlyInAnyOrder(DOOR_EVENT,
                ROBOT_EVENT);
    }

    @Test
    void aBehaviourThatWentAwayByItselfIsBroughtBackByTheNextEvent() {
        bus.publish(bms, DOOR_EVENT);
        clock.runDue();
        installer.last().succeed();
        bus.register(DOOR_EVENT);
        clock.runDue();
        clock.advance(SETTINGS.handoverGraceMs());

        // its bundle stopped: the bus puts its type to the policy again, and the installer lists it as not active
        InstalledBehaviour listed = new InstalledBehaviour();
        listed.symbolicName = DOOR;
        listed.version = "0.1.0";
        listed.state = "RESOLVED";
        installer.active.add(listed);
        assertThat(bus.publish(bms, DOOR_EVENT)).isEqualTo(Disposition.HOLD);
        clock.runDue();
        assertThat(installer.requests).hasSize(2); // the same request: the installer starts it again
        assertThat(installer.finds).hasValue(2);
        assertThat(installer.last().request().reason).contains(DOOR + " is installed but not taking events (RESOLVED)")
                .contains("started again");
        installer.last().succeed();
        bus.register(DOOR_EVENT); // started again: the bus hands the held event over
        clock.runDue();
        clock.advance(SETTINGS.handoverGraceMs());

        // its bundle uninstalled by someone else (not bis:uninstall): the same request installs it again
        listed.state = "UNINSTALLED";
        assertThat(bus.publish(bms, DOOR_EVENT)).isEqualTo(Disposition.HOLD);
        clock.runDue();
        assertThat(installer.requests).hasSize(3);
        assertThat(installer.last().request().reason).contains("had been uninstalled (not with bis:uninstall)");
        installer.last().succeed();
        bus.register(DOOR_EVENT);
        clock.runDue();
        assertThat(bus.handedOver).isEqualTo(3);
        assertThat(bms.history()).extracting(e -> e.kind).containsExactly("INSTALLED", "RESTARTED", "REINSTALLED");
    }

    @Test
    void eventsStillHeldWhenTheGracePeriodEndsAreDecidedAtOnceNotAtTheNextSweep() {
        ManualScheduler time = new ManualScheduler();
        BehaviourManager manager = new BehaviourManager(installer, bus, time, new Alerts(alerts, Runnable::run,
                log.logger, new LongAdder()), log.logger, counters, // sweep: 1 min
                new Settings(1_000, 60_000, 500, 4_000, 10_000, 1_000, 60_000, List.of(), 16, 1_000), () -> false);
        manager.start();
        bus.publish(manager, DOOR_EVENT);
        time.runDue();
        installer.last().succeed(); // but its behaviour went away before it took the held event
        time.runDue();

        time.advance(999);
        assertThat(installer.requests).hasSize(1);
        time.advance(1);
        time.runDue();
        assertThat(installer.requests).as("asked again as the grace period ended, not at the sweep a minute later")
                .hasSize(2);
    }

    @Test
    void eventsHeldAfterTheHandOverThatTheActiveBehaviourDoesNotTakeAreGivenUpOn() {
        bus.publish(bms, DOOR_EVENT);
        clock.runDue();
        installer.last().succeed();
        InstalledBehaviour active = new InstalledBehaviour();
        active.symbolicName = DOOR;
        active.version = "0.1.0";
        active.state = "ACTIVE";
        installer.active.add(active);
        clock.runDue();
        // the behaviour's filter does not take this one: it stays held past the grace period
        assertThat(bus.publish(bms, DOOR_EVENT)).isEqualTo(Disposition.HOLD);
        clock.advance(SETTINGS.handoverGraceMs() + SETTINGS.sweepIntervalMs());

        assertThat(bus.count(DOOR_EVENT)).isZero();
        assertThat(bus.discards).singleElement().asString().contains("does not take");
        assertThat(bus.publish(bms, DOOR_EVENT)).isEqualTo(Disposition.LAST_RESORT);
        assertThat(installer.requests).hasSize(1);
    }

    @Test
    void aRemoteInstallersLateAnswerThatFindsNothingGivesUpTheEventsHeldMeanwhileAndSaysHowMany() {
        installer.remote = true;
        for (int i = 0; i < 7; i++) {
            assertThat(bus.publish(bms, NOBODY)).isEqualTo(Disposition.HOLD);
        }
        installer.pendingFind.resolve(List.of());
        clock.runDue();

        assertThat(bus.count(NOBODY)).isZero();
        assertThat(alerts.of(BehaviourNotFound.class)).singleElement().extracting(a -> a.heldEvents).isEqualTo(7);
        assertThat(bms.history()).singleElement().extracting(e -> e.kind, e -> e.heldEvents)
                .containsExactly("NOT_FOUND", 7);
        assertThat(bus.publish(bms, NOBODY)).isEqualTo(Disposition.LAST_RESORT);
    }

    @Test
    void heldEventsThatNothingWorksOnGetASearchFromTheSweep() {
        // as after a restart of the BMS: the bus holds events of a type the new BMS has no state for
        FakeHold orphaned = new FakeHold();
        BehaviourManager before = new BehaviourManager(installer, orphaned, new ManualScheduler(),
                new Alerts(alerts, Runnable::run, log.logger, new LongAdder()), log.logger, counters, SETTINGS,
                () -> false);
        orphaned.publish(before, DOOR_EVENT);
        BehaviourManager after = new BehaviourManager(installer, orphaned, clock,
                new Alerts(alerts, Runnable::run, log.logger, new LongAdder()), log.logger, counters, SETTINGS,
                () -> false);
        after.start();
        int requests = installer.requests.size();
        clock.advance(SETTINGS.sweepIntervalMs());
        assertThat(installer.requests).hasSize(requests + 1);
        assertThat(installer.last().request().symbolicName).isEqualTo(DOOR);
    }

    @Test
    void publishersRacingOnTheFirstEventsOfATypeCauseOneSearchAndOneInstall() throws Exception {
        int threads = 4;
        CountDownLatch go = new CountDownLatch(1);
        List<Thread> publishers = new ArrayList<>();
        List<Disposition> answers = new java.util.concurrent.CopyOnWriteArrayList<>();
        for (int t = 0; t < threads; t++) {
            Thread p = new Thread(() -> {
                try {
                    go.await();
                } catch (InterruptedException e) {
                    return;
                }
                for (int i = 0; i < 10_000; i++) {
                    answers.add(bms.unhandled(DOOR_EVENT, List.of(DOOR_EVENT), Map::of));
                }
            });
            p.start();
            publishers.add(p);
        }
        go.countDown();
        for (Thread p : publishers) {
            p.join();
        }
        clock.runDue();
        assertThat(answers).hasSize(40_000).containsOnly(Disposition.HOLD);
        assertThat(installer.finds).hasValue(1);
        assertThat(installer.requests).hasSize(1);
    }

    @Test
    void badSettingsAreRefusedNamingTheProperty() {
        assertThatThrownBy(() -> new Settings(0, 1, 1, 1, 1, 1, 1, List.of(), 1, 0))
                .hasMessageContaining("max.held.events must be at least 1, was 0")
                .hasMessageContaining("eu.brain.iot.bms");
        assertThatThrownBy(() -> new Settings(1, 1, 1_000, 10, 1, 1, 1, List.of(), 1, 0))
                .hasMessageContaining("retry.max.ms (10) is below retry.initial.ms (1000)");
        assertThat(SETTINGS.backoff(1)).isEqualTo(500);
        assertThat(SETTINGS.backoff(3)).isEqualTo(2_000);
        assertThat(SETTINGS.backoff(30)).isEqualTo(4_000);
    }

    @Test
    void historyIsBounded() {
        for (int i = 0; i < 40; i++) {
            bus.publish(bms, NOBODY + i);
        }
        clock.runDue();
        List<HistoryEntry> history = bms.history();
        assertThat(history).hasSize(16);
        assertThat(history.get(15).eventTypes).containsExactly(NOBODY + 39);
    }

    private PendingType pendingOf(String type) {
        return BehaviourManagerComponent.pending(bms.states(), bus.held()).stream()
                .filter(p -> p.eventType.equals(type)).findFirst().orElseThrow();
    }
}
