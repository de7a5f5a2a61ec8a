package eu.brain.iot.bis.integration;

import static eu.brain.iot.bis.integration.TestRepository.DOOR;
import static eu.brain.iot.bis.integration.TestRepository.DOOR_CLOSED;
import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.osgi.framework.Bundle;

import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.api.InstallException;
import eu.brain.iot.bis.api.InstallException.Problem;
import eu.brain.iot.bis.api.InstalledBehaviour;

/**
 * An operator's removal or stop holds until an operator allows or installs the behaviour; one stopped by anything
 * else is restarted, and the restart is in the journal and in bis:list.
 */
class OperatorIntegrationTest extends BisTestBase {

    @Test
    void aBehaviourRemovedByAnOperatorIsNotInstalledAutomaticallyUntilAllowed() throws Exception {
        BundleInstaller installer = configure(settings());
        awaitOffered(installer, DOOR_CLOSED);
        value(installer.install(byType(DOOR_CLOSED)));

        assertThat(command("uninstall", DOOR)).contains("uninstalled " + DOOR, "bis:allow");
        assertThat(bundle(DOOR)).isNull();

        InstallException refused = failure(installer.install(byType(DOOR_CLOSED)));
        assertThat(refused.problem()).isEqualTo(Problem.REMOVED_BY_OPERATOR);
        assertThat(refused.getMessage()).contains(DOOR, "bis:allow " + DOOR);
        assertThat(bundle(DOOR)).isNull();
        assertThat(command("list")).contains("removed or stopped by an operator: " + DOOR);

        assertThat(command("allow", DOOR)).contains("may be installed automatically again");
        assertThat(value(installer.install(byType(DOOR_CLOSED))).state).isEqualTo("ACTIVE");
    }

    @Test
    void anOperatorsInstallLiftsTheRemoval() throws Exception {
        BundleInstaller installer = configure(settings());
        awaitOffered(installer, DOOR_CLOSED);
        value(installer.uninstall(DOOR, "not wanted here", true)); // removed before it was ever installed
        assertThat(failure(installer.install(byType(DOOR_CLOSED))).problem())
                .isEqualTo(Problem.REMOVED_BY_OPERATOR);

        assertThat(command("install", "DoorBehaviorClosed")).contains("installed " + DOOR);
        assertThat(bundle(DOOR).getState()).isEqualTo(Bundle.ACTIVE);
        assertThat(installer.installed()).extracting(b -> b.reason).containsExactly("bis:install DoorBehaviorClosed"
                + " by an operator");
    }

    @Test
    void aStoppedBehaviourIsRestartedNotInstalledTwice() throws Exception {
        BundleInstaller installer = configure(settings());
        awaitOffered(installer, DOOR_CLOSED);
        InstalledBehaviour first = value(installer.install(byType(DOOR_CLOSED)));
        bundle(DOOR).stop();
        assertThat(busKnows(DOOR)).isFalse();

        InstalledBehaviour again = value(installer.install(byType(DOOR_CLOSED)));

        assertThat(again.bundleId).isEqualTo(first.bundleId);
        assertThat(again.state).isEqualTo("ACTIVE");
        assertThat(bundleCount(DOOR)).isEqualTo(1);
        assertThat(busKnows(DOOR)).isTrue();
        assertThat(command("list")).contains("restarted: ", "(1 time since the installer started)",
                "why: started again (its bundle was RESOLVED): test: event had no consumer");
        assertThat(java.nio.file.Files.readString(journal.resolve("history.log")))
                .containsPattern("\\trestarted\\t" + DOOR + "\\t");
    }

    @Test
    void aBehaviourStoppedByAnOperatorStaysStoppedUntilAllowedThenTheNextRequestStartsIt() throws Exception {
        BundleInstaller installer = configure(settings());
        awaitOffered(installer, DOOR_CLOSED);
        InstalledBehaviour first = value(installer.install(byType(DOOR_CLOSED)));

        assertThat(command("stop", DOOR)).contains("stopped " + DOOR, "bis:allow " + DOOR, "bis:install " + DOOR);
        assertThat(bundle(DOOR).getState()).isEqualTo(Bundle.RESOLVED);
        InstallException refused = failure(installer.install(byType(DOOR_CLOSED)));
        assertThat(refused.problem()).isEqualTo(Problem.REMOVED_BY_OPERATOR);
        assertThat(refused.getMessage()).contains("bis:stop by an operator", "bis:allow " + DOOR);
        assertThat(bundle(DOOR).getState()).isEqualTo(Bundle.RESOLVED);
        assertThat(command("list")).contains("removed or stopped by an operator: " + DOOR);
        assertThat(java.nio.file.Files.readString(journal.resolve("history.log")))
                .containsPattern("\\tstopped-by-operator\\t" + DOOR + "\\t");

        command("allow", DOOR);
        InstalledBehaviour again = value(installer.install(byType(DOOR_CLOSED)));
        assertThat(again.bundleId).isEqualTo(first.bundleId);
        assertThat(again.state).isEqualTo("ACTIVE");
        assertThat(busKnows(DOOR)).isTrue();
    }
}
