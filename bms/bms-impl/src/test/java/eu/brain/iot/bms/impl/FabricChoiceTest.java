package eu.brain.iot.bms.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.concurrent.atomic.LongAdder;

import org.junit.jupiter.api.Test;

import eu.brain.iot.bis.api.BehaviourCandidate;
import eu.brain.iot.bis.api.InstallException;
import eu.brain.iot.bms.monitoring.api.HistoryEntry;
import eu.brain.iot.eventing.spi.UnhandledEventPolicy.Disposition;

/**
 * The BMS with an installer that spans a fabric: it installs on the node the installer chose (the candidate's
 * {@code node} goes into the request), a failure naming that node is retried by choosing again, and the BMS follows
 * the best-ranked installer as installers come and go ({@link CurrentInstaller}).
 */
class FabricChoiceTest {

    private static final String DOOR_EVENT = "eu.brain.iot.warehouse.OpenDoor";
    private static final String DOOR = "eu.brain.iot.behaviours.door";
    private static final Settings SETTINGS = new Settings(1_000, 60_000, 500, 4_000, 10_000, 1_000, 1_000,
            List.of(), 16, 1_000);

    private final ManualScheduler clock = new ManualScheduler();
    private final FakeHold bus = new FakeHold();
    private final RecordingLogger log = new RecordingLogger();

    private BehaviourManager bms(FakeInstaller installer) {
        BehaviourManager bms = new BehaviourManager(installer, bus, clock, new Alerts(new RecordingBus(),
                Runnable::run, log.logger, new LongAdder()), log.logger, new ManagerCountersImpl(), SETTINGS,
                () -> false);
        bms.start();
        return bms;
    }

    @Test
    void theInstallGoesToTheChosenNodeAndAFailureNamingItIsRetriedByChoosingAgain() {
        FakeInstaller fabric = new FakeInstaller();
        fabric.remote = true; // the fabric answers later
        BehaviourManager bms = bms(fabric);

        assertThat(bus.publish(bms, DOOR_EVENT)).isEqualTo(Disposition.HOLD);
        fabric.pendingFind.resolve(List.of(candidate("node-b")));
        clock.runDue();
        assertThat(fabric.last().request().node).isEqualTo("node-b");

        fabric.last().fail(InstallException.Problem.START_FAILED,
                "node node-b went offline while installing " + DOOR);
        clock.runDue();
        assertThat(bms.states().get(DOOR_EVENT)).isInstanceOf(TypeState.RetryWait.class);
        assertThat(bms.history()).extracting((HistoryEntry h) -> h.reason)
                .anyMatch(r -> r.contains("node node-b went offline"));

        clock.advance(SETTINGS.backoff(1));
        fabric.pendingFind.resolve(List.of(candidate("node-c")));
        clock.runDue();
        assertThat(fabric.finds).as("chosen again, not the same node blindly").hasValue(2);
        assertThat(fabric.last().request().node).isEqualTo("node-c");
        fabric.last().succeed();
        clock.runDue();
        assertThat(bms.states().get(DOOR_EVENT)).isInstanceOf(TypeState.Installed.class);
    }

    @Test
    void theBestRankedInstallerServesAndTheNodesOwnComesBackWhenTheFabricsGoes() {
        FakeInstaller own = new FakeInstaller();
        FakeInstaller fabric = new FakeInstaller();
        own.offer(DOOR_EVENT, DOOR, "0.1.0");
        CurrentInstaller current = new CurrentInstaller();
        assertThat(current.find(List.of(DOOR_EVENT)).isDone()).isTrue();
        assertThat(current.current()).as("none yet").isNull();

        current.add(own, 0, 10);
        current.add(fabric, 100, 42);
        assertThat(current.current()).isSameAs(fabric);
        current.find(List.of(DOOR_EVENT));
        assertThat(fabric.finds).hasValue(1);
        assertThat(own.finds).hasValue(0);

        current.remove(42); // the node left the fabric
        assertThat(current.current()).isSameAs(own);
        current.add(new FakeInstaller(), 0, 11);
        assertThat(current.current()).as("equal ranking: the lowest service id").isSameAs(own);
    }

    private static BehaviourCandidate candidate(String node) {
        BehaviourCandidate c = new BehaviourCandidate();
        c.symbolicName = DOOR;
        c.version = "0.1.0";
        c.consumed = List.of(DOOR_EVENT);
        c.node = node;
        return c;
    }
}
